#include "cli/cli_reference.hpp"

#include <fmt/format.h>

#include <vector>

namespace rollspin::cli {

namespace {

// A command as the generators see it: its words ("report errors"), its
// options and positionals; hidden commands (empty group) are left out.
struct CommandView {
  std::string path;  // "render", "report errors"
  const CLI::App* app;
};

void collect(const CLI::App* app, const std::string& prefix, std::vector<CommandView>& out) {
  for (const CLI::App* sub : app->get_subcommands({})) {
    if (sub->get_group().empty()) continue;
    const std::string path = prefix.empty() ? sub->get_name() : prefix + " " + sub->get_name();
    out.push_back({path, sub});
    collect(sub, path, out);
  }
}

std::vector<CommandView> commands(const CLI::App& cli) {
  std::vector<CommandView> out;
  collect(&cli, "", out);
  return out;
}

std::vector<const CLI::Option*> namedOptions(const CLI::App* app) {
  std::vector<const CLI::Option*> out;
  for (const CLI::Option* o : app->get_options())
    if (o->nonpositional() && !o->get_group().empty()) out.push_back(o);
  return out;
}

std::vector<const CLI::Option*> positionals(const CLI::App* app) {
  std::vector<const CLI::Option*> out;
  for (const CLI::Option* o : app->get_options())
    if (o->get_positional()) out.push_back(o);
  return out;
}

std::vector<std::string> spelledNames(const CLI::Option* o) {
  std::vector<std::string> names;
  for (const auto& s : o->get_snames()) names.push_back("-" + s);
  for (const auto& l : o->get_lnames()) names.push_back("--" + l);
  return names;
}

// A flag expects no value (CLI11 sets expected(0) for add_flag).
bool takesValue(const CLI::Option* o) { return o->get_expected_max() != 0; }
// A positional that names scenes: completed with bundled scene names and *.toml files.
bool isScene(const CLI::Option* o) { return o->get_name() == "scene" || o->get_name() == "scenes"; }

std::string joined(const std::vector<std::string>& items, const std::string& sep) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : sep) + i;
  return out;
}

// roff: backslashes and hyphens escaped, a '.' or '\'' that starts a line
// (the text's first, or one after a newline in a description) neutralised:
// roff would read the line as a request.
std::string roff(const std::string& text) {
  std::string out;
  bool lineStart = true;
  for (char c : text) {
    if (lineStart && (c == '.' || c == '\'')) out += "\\&";
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
    lineStart = c == '\n';
  }
  return out;
}

std::string usageOf(const CommandView& c) {
  std::string usage = "rollspin " + c.path;
  for (const CLI::Option* p : positionals(c.app)) {
    std::string name = p->get_name();
    for (char& ch : name) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    if (p->get_items_expected_max() > 1) name += "...";
    usage += p->get_required() ? " " + name : " [" + name + "]";
  }
  if (!namedOptions(c.app).empty()) usage += " [OPTIONS]";
  if (!c.app->get_subcommands({}).empty()) usage += " COMMAND";
  return usage;
}

// zsh _arguments descriptions may not hold ], :, ' or newlines.
std::string zshText(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '[' || c == ']') out += c == '[' ? '(' : ')';
    else if (c == ':') out += " -";
    else if (c == '\'') out += "'\\''";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

}  // namespace

std::string manPage(const CLI::App& cli, const std::string& version) {
  std::string out = fmt::format(".TH ROLLSPIN 1 \"\" \"rollspin {}\" \"User Commands\"\n", version);
  std::string summary = cli.get_description();
  if (summary.starts_with("rollspin: ")) summary = summary.substr(10);
  out += ".SH NAME\nrollspin \\- " + roff(summary) + "\n";
  out += ".SH SYNOPSIS\n.B rollspin\n[\\fB\\-\\-verbose\\fR] \\fICOMMAND\\fR [\\fIARGS\\fR]\n";
  out +=
      ".SH DESCRIPTION\nrollspin solves a ball rolling without slipping or spinning on a surface as a spin\\-1/2 "
      "in a magnetic field, with arc length as time, and renders stills, figures and clips of it off screen. "
      "A \\fISCENE\\fR is a TOML file, or the name of a bundled scene (\\fBrollspin scenes\\fR lists them; "
      "\\fBrollspin keys\\fR lists every key a scene accepts).\n";
  out += ".SH GLOBAL OPTIONS\n";
  for (const CLI::Option* o : namedOptions(&cli))
    out += ".TP\n.B " + roff(joined(spelledNames(o), ", ")) + "\n" + roff(o->get_description()) + "\n";
  out += ".SH COMMANDS\n";
  for (const CommandView& c : commands(cli)) {
    out += ".SS \"" + roff(usageOf(c)) + "\"\n" + roff(c.app->get_description()) + "\n";
    for (const CLI::Option* p : positionals(c.app))
      out += ".TP\n.I " + roff(p->get_name()) + "\n" + roff(p->get_description()) + "\n";
    for (const CLI::Option* o : namedOptions(c.app)) {
      std::string names = roff(joined(spelledNames(o), ", "));
      if (takesValue(o)) names += " \\fIVALUE\\fR";
      out += ".TP\n\\fB" + names + "\\fR\n" + roff(o->get_description()) + "\n";
    }
  }
  out +=
      ".SH ENVIRONMENT\n"
      ".TP\n.B ROLLSPIN_SCENE_PATH\nFolders (':'\\-separated) searched first for a bare scene name.\n"
      ".TP\n.B ROLLSPIN_GL\nThe GL backend (see \\fBrollspin info\\fR).\n"
      ".TP\n.B ROLLSPIN_EGL_DEVICE\nThe EGL device (an index or a DRM path).\n";
  out += ".SH FILES\n.TP\n.I <prefix>/share/rollspin/scenes\nThe bundled scenes.\n";
  out +=
      ".SH EXIT STATUS\n0 on success; 1 on a runtime failure (and for \\fBcompare\\fR, images that differ); "
      "2 on bad input (a scene, an option, a missing file).\n";
  out += ".SH SEE ALSO\nThe scene reference: docs/scene\\-reference.md, or \\fBrollspin keys\\fR.\n";
  return out;
}

std::string bashCompletion(const CLI::App& cli) {
  std::vector<std::string> top;
  for (const CLI::App* sub : cli.get_subcommands({}))
    if (!sub->get_group().empty()) top.push_back(sub->get_name());
  std::vector<std::string> global;
  for (const CLI::Option* o : namedOptions(&cli))
    for (const auto& n : spelledNames(o)) global.push_back(n);

  std::string cases;
  for (const CommandView& c : commands(cli)) {
    std::vector<std::string> words, valued, subs;
    for (const CLI::Option* o : namedOptions(c.app))
      for (const auto& n : spelledNames(o)) {
        words.push_back(n);
        if (takesValue(o)) valued.push_back(n);
      }
    for (const CLI::App* sub : c.app->get_subcommands({}))
      if (!sub->get_group().empty()) subs.push_back(sub->get_name());
    bool scene = false;
    for (const CLI::Option* p : positionals(c.app)) scene = scene || isScene(p);
    cases += fmt::format("    \"{}\")\n      opts=\"{}\"; valued=\"{}\"; subs=\"{}\"; scene={} ;;\n", c.path,
                         joined(words, " "), joined(valued, " "), joined(subs, " "), scene ? 1 : 0);
  }
  return fmt::format(R"BASH(# bash completion for rollspin (generated by `rollspin generate bash`; do not edit)
_rollspin_scene_names() {{
  "${{COMP_WORDS[0]}}" scenes --names 2>/dev/null
}}

_rollspin() {{
  local cur prev cmd="" i word opts="" valued="" subs="" scene=0
  cur="${{COMP_WORDS[COMP_CWORD]}}"
  prev="${{COMP_WORDS[COMP_CWORD-1]}}"
  # The command words typed so far ("report errors"): the words that name commands.
  for ((i = 1; i < COMP_CWORD; i++)); do
    word="${{COMP_WORDS[i]}}"
    [[ "$word" == -* ]] && continue
    case "${{cmd:+$cmd }}$word" in
{known}) cmd="${{cmd:+$cmd }}$word" ;;
    esac
  done
  if [[ -z "$cmd" ]]; then
    COMPREPLY=($(compgen -W "{top} {global}" -- "$cur"))
    return
  fi
  case "$cmd" in
{cases}  esac
  # An option's value: files for outputs and folders, nothing to guess otherwise.
  if [[ " $valued " == *" $prev "* ]]; then
    case "$prev" in
      -o|--output|--output-dir|--diff|--shader-dir) COMPREPLY=($(compgen -f -- "$cur")) ;;
    esac
    return
  fi
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$opts {global}" -- "$cur"))
  elif [[ -n "$subs" ]]; then
    COMPREPLY=($(compgen -W "$subs" -- "$cur"))
  elif [[ "$scene" == 1 ]]; then
    COMPREPLY=($(compgen -W "$(_rollspin_scene_names)" -- "$cur") $(compgen -f -X '!*.toml' -- "$cur") $(compgen -d -- "$cur"))
  else
    COMPREPLY=($(compgen -f -- "$cur"))
  fi
}}
complete -F _rollspin rollspin
)BASH",
                     fmt::arg("known",
                              [&] {
                                std::vector<std::string> paths;
                                for (const CommandView& c : commands(cli)) paths.push_back("\"" + c.path + "\"");
                                return "      " + joined(paths, "|");
                              }()),
                     fmt::arg("top", joined(top, " ")), fmt::arg("global", joined(global, " ")),
                     fmt::arg("cases", cases));
}

std::string zshCompletion(const CLI::App& cli) {
  // One function per command with its _arguments specs; a command with
  // subcommands describes them for the next word.
  std::string functions;
  auto fnName = [](const std::string& path) {
    std::string name = "_rollspin_cmd_" + path;
    for (char& c : name)
      if (c == ' ' || c == '-') c = '_';
    return name;
  };
  auto describeSubs = [&](const CLI::App* app) {
    std::string out = "    local -a cmds\n    cmds=(\n";
    for (const CLI::App* sub : app->get_subcommands({}))
      if (!sub->get_group().empty()) out += "      '" + sub->get_name() + ":" + zshText(sub->get_description()) + "'\n";
    return out + "    )\n";
  };
  auto globalSpecs = [&] {
    std::string out;
    for (const CLI::Option* o : namedOptions(&cli))
      if (o->get_name() != "--help")  // each command has its own
        for (const auto& n : spelledNames(o)) out += "    '" + n + "[" + zshText(o->get_description()) + "]' \\\n";
    return out;
  };
  for (const CommandView& c : commands(cli)) {
    std::string specs;
    for (const CLI::Option* o : namedOptions(c.app)) {
      for (const auto& n : spelledNames(o)) {
        std::string spec = "'" + n + "[" + zshText(o->get_description()) + "]";
        if (takesValue(o)) {
          const bool file = n == "-o" || n == "--output" || n == "--output-dir" || n == "--diff" || n == "--shader-dir";
          spec += std::string(":value:") + (file ? "_files" : " ");
        }
        specs += "    " + spec + "' \\\n";
      }
    }
    int index = 1;
    for (const CLI::Option* p : positionals(c.app)) {
      const std::string action = isScene(p) ? "_rollspin_scenes" : "_files";
      const std::string many = p->get_items_expected_max() > 1 ? "*" : std::to_string(index++);
      specs += "    '" + many + ":" + p->get_name() + ":" + action + "' \\\n";
    }
    const bool hasSubs = !c.app->get_subcommands({}).empty();
    std::string body = fmt::format("{}() {{\n", fnName(c.path));
    if (hasSubs) {
      body += describeSubs(c.app);
      body += "  _arguments -C \\\n" + globalSpecs() + specs + "    '1:command:->cmds' '*::arg:->args'\n";
      body += "  case $state in\n    (cmds) _describe 'command' cmds ;;\n    (args)\n      case $words[1] in\n";
      for (const CLI::App* sub : c.app->get_subcommands({}))
        if (!sub->get_group().empty())
          body += fmt::format("        ({}) {} ;;\n", sub->get_name(), fnName(c.path + " " + sub->get_name()));
      body += "      esac ;;\n  esac\n}\n\n";
    } else {
      body += "  _arguments \\\n" + globalSpecs() + specs + "    && return 0\n}\n\n";
    }
    functions += body;
  }
  std::string dispatch;
  for (const CLI::App* sub : cli.get_subcommands({}))
    if (!sub->get_group().empty())
      dispatch += fmt::format("        ({}) {} ;;\n", sub->get_name(), fnName(sub->get_name()));
  return "#compdef rollspin\n# zsh completion for rollspin (generated by `rollspin generate zsh`; do not edit)\n\n"
         "_rollspin_scenes() {\n  local -a names\n  names=(${(f)\"$(rollspin scenes --names 2>/dev/null)\"})\n"
         "  _alternative 'scenes:bundled scene:compadd -a names' 'files:scene file:_files -g \"*.toml\"'\n}\n\n" +
         functions + "_rollspin() {\n  local curcontext=\"$curcontext\" state line\n" + describeSubs(&cli) +
         "  _arguments -C \\\n" + globalSpecs() +
         "    '1:command:->cmds' '*::arg:->args'\n  case $state in\n    (cmds) _describe 'command' cmds ;;\n"
         "    (args)\n      case $words[1] in\n" +
         dispatch + "      esac ;;\n  esac\n}\n\n_rollspin \"$@\"\n";
}

}  // namespace rollspin::cli
