#!/usr/bin/env python3
"""Lists the functions in C++ sources longer than a limit (lines from the
signature's first line to the closing brace). A brace-matching reader, not a
compiler: comments, strings and character literals are blanked first; a
brace opened at namespace or class scope after a ")" (with qualifiers, a
trailing return type or a constructor's initialisers after it) opens a
function; lambdas and blocks inside count toward their function.
Usage: function_lengths.py [--limit N] [--allow-from DOC] PATH...
--allow-from reads the exempt functions (pure data tables) from DOC's
section "## Functions that fit on a screen": each `path:function` written
there in backticks (docs/design.md). Exit 1 when any other function is over
the limit; ctest SourceLayout.NoFunctionOver100Lines runs it on src/ and
python/src/."""
import argparse, pathlib, re, sys

def blank(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i); j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2); j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) + len(m.group(1)) + 2
            out.append('""' + re.sub(r'[^\n]', ' ', text[i + 2:end])); i = end
        elif c in '"\'' and not (c == "'" and i > 0 and text[i-1].isalnum() and text[i+1:i+2].isdigit()):
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            out.append(c + ' ' * (j - i - 1) + c); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)

def functions(path):
    text = blank(path.read_text())
    stack = []          # kinds of the open braces
    stmt_start = 0      # offset where the current statement at this scope began
    found = []
    for i, c in enumerate(text):
        if c in ';':
            if not stack or stack[-1] in ('namespace', 'class'):
                stmt_start = i + 1
        elif c == '{':
            if stack and stack[-1] not in ('namespace', 'class'):
                stack.append('block'); continue
            head = text[stmt_start:i]
            flat = ' '.join(head.split())
            if re.search(r'\bnamespace\b', flat) or re.match(r'(extern\s+"C")', flat):
                kind = 'namespace'
            elif re.match(r'(template\s*<.*>\s*)?(class|struct|union|enum)\b', flat) and '(' not in flat.split('{')[0].split(':')[0]:
                kind = 'class'
            elif ')' in flat and not re.search(r'=\s*[^=]*$', flat.split(')')[-1]) :
                kind = 'function'
            else:
                kind = 'block'
            if kind == 'function':
                # the signature starts at the first non-blank of the statement
                k = stmt_start
                while k < i and text[k].isspace(): k += 1
                stack.append(('function', text.count('\n', 0, k) + 1, flat))
            else:
                stack.append(kind)
            if kind in ('namespace', 'class'):
                stmt_start = i + 1
        elif c == '}':
            if not stack: continue
            top = stack.pop()
            if isinstance(top, tuple):
                end = text.count('\n', 0, i) + 1
                m = re.findall(r'([~\w:]+(?:<[^()]*>)?|operator\S*)\s*\(', top[2])
                name = m[0] if m else top[2][:40]
                found.append((end - top[1] + 1, top[1], name))
            if not stack or stack[-1] in ('namespace', 'class'):
                stmt_start = i + 1
        elif c == ':' and stack and stack[-1] == 'class':
            # access specifiers end a "statement" in a class
            before = text[stmt_start:i].split()
            if before and before[-1] in ('public', 'private', 'protected'):
                stmt_start = i + 1
    return found

def rel(path):
    """The path from the checkout's root (the folder above scripts/)."""
    root = pathlib.Path(__file__).resolve().parent.parent
    try:
        return str(pathlib.Path(path).resolve().relative_to(root))
    except ValueError:
        return str(path)

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--limit', type=int, default=100)
    ap.add_argument('--allow-from', help='a Markdown file whose "Functions that fit on a screen" section names the exempt `path:function`s')
    ap.add_argument('paths', nargs='+')
    a = ap.parse_args()
    allow = set()
    if a.allow_from:
        text = open(a.allow_from, encoding='utf-8').read()
        m = re.search(r'^## Functions that fit on a screen\n(.*?)(?=^## |\Z)', text, re.S | re.M)
        if not m:
            sys.exit(f'{a.allow_from}: no section "## Functions that fit on a screen"')
        allow = set(re.findall(r'`((?:src|python)/[^`:]+:[^`]+)`', m.group(1)))
    over = []
    for p in a.paths:
        files = sorted(pathlib.Path(p).rglob('*.[ch]pp')) if pathlib.Path(p).is_dir() else [pathlib.Path(p)]
        for f in files:
            for length, line, name in functions(f):
                if length > a.limit and f'{rel(f)}:{name}' not in allow:
                    over.append((length, f'{f}:{line}', name))
    for length, where, name in sorted(over, reverse=True):
        print(f'{length:5d}  {where}  {name}')
    if over:
        print(f'{len(over)} function(s) over {a.limit} lines: split them by concept (docs/design.md, '
              '"Functions that fit on a screen"; a pure data table may be listed there instead)')
    return 1 if over else 0

sys.exit(main())
