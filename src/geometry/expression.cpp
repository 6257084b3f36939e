#include "geometry/expression.hpp"

#include <muParser.h>

#include <cmath>
#include <map>
#include <numbers>

namespace rollspin::geometry {

namespace {

// Our own callbacks for muparser: their addresses identify the function in
// the compiled bytecode, so the Jet evaluator knows which derivative to apply.
enum class Fn {
  Neg,
  Plus,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sinh,
  Cosh,
  Tanh,
  Asinh,
  Acosh,
  Atanh,
  Exp,
  Log,
  Log10,
  Log2,
  Sqrt,
  Abs,
  Atan2,
  Pow
};

double fNeg(double a) { return -a; }
double fPlus(double a) { return a; }
double fSin(double a) { return std::sin(a); }
double fCos(double a) { return std::cos(a); }
double fTan(double a) { return std::tan(a); }
double fAsin(double a) { return std::asin(a); }
double fAcos(double a) { return std::acos(a); }
double fAtan(double a) { return std::atan(a); }
double fSinh(double a) { return std::sinh(a); }
double fCosh(double a) { return std::cosh(a); }
double fTanh(double a) { return std::tanh(a); }
double fAsinh(double a) { return std::asinh(a); }
double fAcosh(double a) { return std::acosh(a); }
double fAtanh(double a) { return std::atanh(a); }
double fExp(double a) { return std::exp(a); }
double fLog(double a) { return std::log(a); }
double fLog10(double a) { return std::log10(a); }
double fLog2(double a) { return std::log2(a); }
double fSqrt(double a) { return std::sqrt(a); }
double fAbs(double a) { return std::abs(a); }
double fAtan2(double a, double b) { return std::atan2(a, b); }
double fPow(double a, double b) { return std::pow(a, b); }

struct Unary {
  const char* name;
  double (*fn)(double);
  Fn id;
};
constexpr Unary kUnary[] = {
    {"sin", fSin, Fn::Sin},    {"cos", fCos, Fn::Cos},       {"tan", fTan, Fn::Tan},       {"asin", fAsin, Fn::Asin},
    {"acos", fAcos, Fn::Acos}, {"atan", fAtan, Fn::Atan},    {"sinh", fSinh, Fn::Sinh},    {"cosh", fCosh, Fn::Cosh},
    {"tanh", fTanh, Fn::Tanh}, {"asinh", fAsinh, Fn::Asinh}, {"acosh", fAcosh, Fn::Acosh}, {"atanh", fAtanh, Fn::Atanh},
    {"exp", fExp, Fn::Exp},    {"log", fLog, Fn::Log},       {"ln", fLog, Fn::Log},        {"log10", fLog10, Fn::Log10},
    {"log2", fLog2, Fn::Log2}, {"sqrt", fSqrt, Fn::Sqrt},    {"abs", fAbs, Fn::Abs},
};

enum class Op {
  Value,
  Variable,
  Add,
  Sub,
  Mul,
  Div,
  Pow,
  Lt,
  Le,
  Gt,
  Ge,
  Eq,
  Ne,
  And,
  Or,
  Call1,
  Call2,
  If,
  Else,
  EndIf
};

struct Instruction {
  Op op = Op::Value;
  double value = 0.0;  // Op::Value
  int variable = 0;    // Op::Variable
  Fn fn = Fn::Neg;     // Op::Call1 / Call2
  int offset = 0;      // Op::If / Else: jump distance
};

constexpr double kLog10e = 0.43429448190325182765;
constexpr double kLog2e = 1.44269504088896340736;

template <typename T>
T applyUnary(Fn f, const T& x) {
  using std::abs, std::acos, std::acosh, std::asin, std::asinh, std::atan, std::atanh, std::cos, std::cosh, std::exp,
      std::log, std::sin, std::sinh, std::sqrt, std::tan, std::tanh;
  switch (f) {
    case Fn::Neg: return -x;
    case Fn::Plus: return x;
    case Fn::Sin: return sin(x);
    case Fn::Cos: return cos(x);
    case Fn::Tan: return tan(x);
    case Fn::Asin: return asin(x);
    case Fn::Acos: return acos(x);
    case Fn::Atan: return atan(x);
    case Fn::Sinh: return sinh(x);
    case Fn::Cosh: return cosh(x);
    case Fn::Tanh: return tanh(x);
    case Fn::Asinh: return asinh(x);
    case Fn::Acosh: return acosh(x);
    case Fn::Atanh: return atanh(x);
    case Fn::Exp: return exp(x);
    case Fn::Log: return log(x);
    case Fn::Log10: return kLog10e * log(x);
    case Fn::Log2: return kLog2e * log(x);
    case Fn::Sqrt: return sqrt(x);
    case Fn::Abs: return abs(x);
    default: return x;
  }
}

double valueOf(double x) { return x; }
double valueOf(const Jet& x) { return x.v; }

// atan2(y, x): atan(y/x) and −atan(x/y) have its derivatives (away from the
// origin); take the better-conditioned one, then put atan2's value back.
Jet atan2Jet(const Jet& y, const Jet& x) {
  Jet r = std::abs(x.v) >= std::abs(y.v) ? atan(y / x) : -atan(x / y);
  r.v = std::atan2(y.v, x.v);
  return r;
}
double applyBinary(Fn f, double a, double b) { return f == Fn::Atan2 ? std::atan2(a, b) : std::pow(a, b); }
Jet applyBinary(Fn f, const Jet& a, const Jet& b) { return f == Fn::Atan2 ? atan2Jet(a, b) : pow(a, b); }
double power(double a, double b) { return std::pow(a, b); }
Jet power(const Jet& a, const Jet& b) { return pow(a, b); }

}  // namespace

struct Expression::Compiled {
  std::vector<Instruction> program;
  std::size_t maxStack = 0;
};

Expression::Expression(std::string text, std::vector<std::string> variables)
    : text_(std::move(text)), compiled_(std::make_unique<Compiled>()) {
  mu::Parser parser;
  parser.ClearFun();
  parser.ClearInfixOprt();
  parser.ClearPostfixOprt();
  parser.EnableOptimizer(false);  // keep the plain RPN: no fused tokens
  parser.DefineInfixOprt("-", fNeg);
  parser.DefineInfixOprt("+", fPlus);
  std::map<void*, Fn> functions{{reinterpret_cast<void*>(fNeg), Fn::Neg},
                                {reinterpret_cast<void*>(fPlus), Fn::Plus},
                                {reinterpret_cast<void*>(fAtan2), Fn::Atan2},
                                {reinterpret_cast<void*>(fPow), Fn::Pow}};
  for (const Unary& u : kUnary) {
    parser.DefineFun(u.name, u.fn);
    functions[reinterpret_cast<void*>(u.fn)] = u.id;
  }
  parser.DefineFun("atan2", fAtan2);
  parser.DefineFun("pow", fPow);
  parser.DefineConst("pi", std::numbers::pi);
  double storage[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < variables.size() && i < 2; ++i) parser.DefineVar(variables[i], &storage[i]);

  try {
    parser.SetExpr(text_);
    (void)parser.Eval();  // compiles the bytecode
  } catch (const mu::Parser::exception_type& e) {
    // muparser appends its own 0-based "at position N"; the caller reports
    // the position (1-based, and as a file column), so drop it here.
    std::string message = e.GetMsg();
    if (const auto cut = message.find(" at position "); cut != std::string::npos) message.erase(cut);
    throw ExpressionError(static_cast<int>(e.GetPos()), message);
  }
  if (parser.GetNumResults() != 1) throw ExpressionError(0, "expected one expression, got a comma-separated list");

  // Translate muparser's bytecode into our own program once.
  const mu::ParserByteCode& bytecode = parser.GetByteCode();
  const mu::SToken* tokens = bytecode.GetBase();
  std::size_t depth = 0;
  for (std::size_t i = 0; i < bytecode.GetSize() && tokens[i].Cmd != mu::cmEND; ++i) {
    const mu::SToken& tok = tokens[i];
    Instruction ins;
    switch (tok.Cmd) {
      case mu::cmVAL:
        ins.op = Op::Value;
        ins.value = tok.Val.data2;
        ++depth;
        break;
      case mu::cmVAR:
        ins.op = Op::Variable;
        ins.variable = tok.Val.ptr == &storage[1] ? 1 : 0;
        ++depth;
        break;
      case mu::cmADD: ins.op = Op::Add; break;
      case mu::cmSUB: ins.op = Op::Sub; break;
      case mu::cmMUL: ins.op = Op::Mul; break;
      case mu::cmDIV: ins.op = Op::Div; break;
      case mu::cmPOW: ins.op = Op::Pow; break;
      case mu::cmLT: ins.op = Op::Lt; break;
      case mu::cmLE: ins.op = Op::Le; break;
      case mu::cmGT: ins.op = Op::Gt; break;
      case mu::cmGE: ins.op = Op::Ge; break;
      case mu::cmEQ: ins.op = Op::Eq; break;
      case mu::cmNEQ: ins.op = Op::Ne; break;
      case mu::cmLAND: ins.op = Op::And; break;
      case mu::cmLOR: ins.op = Op::Or; break;
      case mu::cmIF:
        ins.op = Op::If;
        ins.offset = tok.Oprt.offset;
        break;
      case mu::cmELSE:
        ins.op = Op::Else;
        ins.offset = tok.Oprt.offset;
        break;
      case mu::cmENDIF: ins.op = Op::EndIf; break;
      case mu::cmFUNC: {
        const auto it = functions.find(reinterpret_cast<void*>(tok.Fun.cb._pRawFun));
        if (it == functions.end() || (tok.Fun.argc != 1 && tok.Fun.argc != 2))
          throw ExpressionError(0, "unsupported function in the expression");
        ins.op = tok.Fun.argc == 1 ? Op::Call1 : Op::Call2;
        ins.fn = it->second;
        break;
      }
      default:
        throw ExpressionError(0, "unsupported construct in the expression (code " + std::to_string(tok.Cmd) + ")");
    }
    compiled_->maxStack = std::max(compiled_->maxStack, depth);
    compiled_->program.push_back(ins);
  }
  if (compiled_->program.empty()) throw ExpressionError(0, "empty expression");
  compiled_->maxStack += 2;
}

Expression::~Expression() = default;

template <typename T>
T Expression::evaluate(const T& a, const T& b) const {
  // A small fixed stack: surface expressions are short; fall back to the heap.
  T local[32];
  std::vector<T> heap;
  T* stack = local;
  if (compiled_->maxStack > 32) {
    heap.resize(compiled_->maxStack);
    stack = heap.data();
  }
  int top = -1;
  const auto& program = compiled_->program;
  for (std::size_t i = 0; i < program.size(); ++i) {
    const Instruction& ins = program[i];
    switch (ins.op) {
      case Op::Value: stack[++top] = T(ins.value); break;
      case Op::Variable: stack[++top] = ins.variable == 0 ? a : b; break;
      case Op::Add:
        --top;
        stack[top] = stack[top] + stack[top + 1];
        break;
      case Op::Sub:
        --top;
        stack[top] = stack[top] - stack[top + 1];
        break;
      case Op::Mul:
        --top;
        stack[top] = stack[top] * stack[top + 1];
        break;
      case Op::Div:
        --top;
        stack[top] = stack[top] / stack[top + 1];
        break;
      case Op::Pow:
        --top;
        stack[top] = power(stack[top], stack[top + 1]);
        break;
      case Op::Lt:
        --top;
        stack[top] = T(valueOf(stack[top]) < valueOf(stack[top + 1]) ? 1.0 : 0.0);
        break;
      case Op::Le:
        --top;
        stack[top] = T(valueOf(stack[top]) <= valueOf(stack[top + 1]) ? 1.0 : 0.0);
        break;
      case Op::Gt:
        --top;
        stack[top] = T(valueOf(stack[top]) > valueOf(stack[top + 1]) ? 1.0 : 0.0);
        break;
      case Op::Ge:
        --top;
        stack[top] = T(valueOf(stack[top]) >= valueOf(stack[top + 1]) ? 1.0 : 0.0);
        break;
      case Op::Eq:
        --top;
        stack[top] = T(valueOf(stack[top]) == valueOf(stack[top + 1]) ? 1.0 : 0.0);
        break;
      case Op::Ne:
        --top;
        stack[top] = T(valueOf(stack[top]) != valueOf(stack[top + 1]) ? 1.0 : 0.0);
        break;
      case Op::And:
        --top;
        stack[top] = T(valueOf(stack[top]) != 0.0 && valueOf(stack[top + 1]) != 0.0 ? 1.0 : 0.0);
        break;
      case Op::Or:
        --top;
        stack[top] = T(valueOf(stack[top]) != 0.0 || valueOf(stack[top + 1]) != 0.0 ? 1.0 : 0.0);
        break;
      case Op::Call1: stack[top] = applyUnary(ins.fn, stack[top]); break;
      case Op::Call2:
        --top;
        stack[top] = applyBinary(ins.fn, stack[top], stack[top + 1]);
        break;
      case Op::If:
        // muparser's convention: a false condition jumps to the else branch.
        if (valueOf(stack[top--]) == 0.0) i += static_cast<std::size_t>(ins.offset);
        break;
      case Op::Else: i += static_cast<std::size_t>(ins.offset); break;
      case Op::EndIf: break;
    }
  }
  return stack[top];
}

double Expression::value(double a, double b) const { return evaluate<double>(a, b); }

Jet Expression::jet(const Jet& a, const Jet& b) const { return evaluate<Jet>(a, b); }

}  // namespace rollspin::geometry
