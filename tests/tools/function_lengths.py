#!/usr/bin/env python3
"""Function lengths of the project's C++ code, by brace counting.

Each function body (free functions, member functions in and out of their class, constructors,
operators; a lambda counts as part of the function it is written in) is measured from the first
line of its signature to its closing brace. Prints a table of the functions longer than --min
lines (default 80), longest first, and how many run past 80 and 150 lines.

With --max N, exits 1 when a function longer than N lines does not say why: a comment containing
`long-function:` on the signature's line or in the comment block right above it, e.g.

    // long-function: one switch over every key of the scene file, each case a few lines.
    Expected<SceneDocument> parseSceneJson(...) {

usage: tests/tools/function_lengths.py [--min 80] [--max 150] [--markdown] [PATH...]
       (PATH: files or folders; default app/ modeling/ lighting/ render/)
"""
import argparse
import os
import re
import sys

MARKER = "long-function:"
DEFAULT_PATHS = ["app", "modeling", "lighting", "render"]
EXTENSIONS = (".cpp", ".h", ".hpp", ".cc")
CONTROL = {"if", "for", "while", "switch", "catch", "do", "else", "try", "return", "sizeof",
           "decltype", "alignof", "static_assert", "requires", "noexcept", "alignas"}


def strip_code(text):
    """The text with comments, string and character literals and preprocessor lines blanked
    (newlines kept, so offsets and line numbers stay), and the comments as (line, text) pairs."""
    out = list(text)
    comments = []  # (first line, last line, text)
    i, n = 0, len(text)
    line = 1
    at_line_start = True

    def blank(a, b):
        for k in range(a, b):
            if out[k] != "\n":
                out[k] = " "

    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            at_line_start = True
            i += 1
            continue
        if at_line_start and c == "#":
            # A preprocessor directive, with its continuation lines.
            j = i
            while j < n:
                if text[j] == "\n" and text[j - 1] != "\\":
                    break
                j += 1
            blank(i, j)
            line += text.count("\n", i, j)
            i = j
            continue
        if not c.isspace():
            at_line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            comments.append((line, line, text[i:j]))
            blank(i, j)
            i = j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            last = line + text.count("\n", i, j)
            comments.append((line, last, text[i:j]))
            blank(i, j)
            line = last
            i = j
            continue
        m = re.match(r'(?:u8|u|U|L)?R"([^()\\ ]{0,16})\(', text[i:i + 24])
        if m and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
            line += text.count("\n", i, j)
            blank(i, j)
            i = j
            continue
        if c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum()
                                          and i + 1 < n and text[i + 1].isalnum())):
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            blank(i + 1, j - 1)
            i = j
            continue
        i += 1
    return "".join(out), comments


def function_name(header):
    """The (qualified) name in a function's signature, or None if the header is no function."""
    h = " ".join(header.split())
    m = re.search(r"\boperator\b", h)
    if m:
        rest = h[m.end():].lstrip()
        op = "()" if rest.startswith("()") else rest.split("(", 1)[0].strip()
        start = h[:m.start()]
        q = re.search(r"((?:[A-Za-z_]\w*(?:<[^<>]*>)?\s*::\s*)*)$", start)
        return (q.group(1).replace(" ", "") if q else "") + "operator" + op
    depth = 0
    for k, ch in enumerate(h):
        if ch == "<":
            depth += 1
        elif ch == ">" and depth > 0:
            depth -= 1
        elif ch == "(" and depth == 0:
            q = re.search(r"((?:[A-Za-z_]\w*(?:<[^<>]*>)?\s*::\s*)*~?[A-Za-z_]\w*)\s*$", h[:k])
            if not q:
                return None
            name = q.group(1).replace(" ", "")
            if name.split("::")[-1] in CONTROL:
                return None
            return name
    return None


def classify(header):
    """What an opening brace after `header` (the text since the last ; { or }) opens."""
    h = " ".join(header.split())
    if not h:
        return "block", None
    if re.search(r"\bnamespace\b", h) or re.match(r'^extern\s*"', header.strip()):
        return "scope", None
    if re.search(r"\benum\b", h):
        return "block", None
    m = re.match(r"^(?:template\s*<.*>\s*)?(?:class|struct|union)\s+(?:\[\[[^]]*\]\]\s*)?"
                 r"(?:[A-Z_]+_EXPORT\s+)?([A-Za-z_]\w*)", h)
    if m and "(" not in h.split(":")[0]:
        return "class", m.group(1)
    # An initializer (`= {`, `x{...}` without a parameter list) or a lambda at namespace level.
    paren = h.find("(")
    eq = re.search(r"(?<![=!<>])=(?!=)", h)
    if eq and (paren < 0 or eq.start() < paren) and "operator" not in h:
        return "block", None
    if paren < 0 or ")" not in h:
        return "block", None
    name = function_name(h)
    if name is None:
        return "block", None
    return "function", name


def member_init_brace(header):
    """True when a { in `header` is a brace initializer in a constructor's member list:
    Foo() : a_{1}, b_{2} {  (the header then ends with the member's name)."""
    h = " ".join(header.split())
    return bool(re.search(r"\)\s*(?:noexcept\s*)?:\s*.*[A-Za-z_]\w*\s*$", h)) and \
        not re.search(r"\b(class|struct)\b", h.split("(")[0])


def measure(path):
    text = open(path, encoding="utf-8", errors="replace").read()
    code, comments = strip_code(text)
    line_of = []
    ln = 1
    for ch in code:
        line_of.append(ln)
        if ch == "\n":
            ln += 1
    results = []
    # Stack entries: (kind, name); kinds: scope, class, function, block.
    stack = []
    header_start = 0
    i, n = 0, len(code)
    fn_start = None
    while i < n:
        c = code[i]
        in_function = any(k == "function" for k, _ in stack)
        if c == "{":
            if in_function:
                stack.append(("block", None))
            else:
                header = code[header_start:i]
                if member_init_brace(header) and header.strip():
                    # Skip the braced member initializer, keep reading the constructor's header.
                    depth, j = 0, i
                    while j < n:
                        if code[j] == "{":
                            depth += 1
                        elif code[j] == "}":
                            depth -= 1
                            if depth == 0:
                                break
                        j += 1
                    i = j + 1
                    continue
                kind, name = classify(header)
                if kind == "function":
                    classes = [nm for k, nm in stack if k == "class"]
                    if classes and "::" not in name:
                        name = "::".join(classes) + "::" + name
                    # The signature's first line: the header's first non-blank character.
                    off = header_start + (len(header) - len(header.lstrip()))
                    fn_start = (line_of[off], name)
                stack.append((kind, name if kind != "function" else fn_start))
            header_start = i + 1
        elif c == "}":
            if stack:
                kind, info = stack.pop()
                if kind == "function":
                    first, name = info
                    results.append((line_of[i] - first + 1, name, path, first))
            header_start = i + 1
        elif c == ";":
            header_start = i + 1
        i += 1
    # Mark the functions whose signature line or comment block above carries the marker.
    marked = set()
    comment_lines = {}
    for first, last, txt in comments:
        for k, part in enumerate(txt.split("\n")):
            comment_lines[first + k] = comment_lines.get(first + k, "") + part
    src_lines = text.split("\n")
    for length, name, _, first in results:
        if MARKER in comment_lines.get(first, ""):
            marked.add((name, first))
            continue
        k = first - 1
        # Walk up over template lines and the comment block directly above.
        while k >= 1 and (k in comment_lines or src_lines[k - 1].strip().startswith("template")):
            if MARKER in comment_lines.get(k, ""):
                marked.add((name, first))
                break
            k -= 1
    return [(length, name, p, first, (name, first) in marked) for length, name, p, first in results]


def collect(paths):
    files = []
    for p in paths:
        if os.path.isdir(p):
            for root, _, names in os.walk(p):
                files += [os.path.join(root, f) for f in names if f.endswith(EXTENSIONS)]
        elif p.endswith(EXTENSIONS):
            files.append(p)
    return sorted(files)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("paths", nargs="*", help="files or folders (default: app modeling lighting render)")
    ap.add_argument("--min", type=int, default=80, help="list the functions longer than this (80)")
    ap.add_argument("--max", type=int, default=None,
                    help=f"fail when a function longer than this lacks a '{MARKER}' comment")
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    args = ap.parse_args()
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    paths = args.paths or [os.path.join(root, p) for p in DEFAULT_PATHS]
    rows = []
    for f in collect(paths):
        rows += measure(f)
    rows.sort(key=lambda r: (-r[0], r[2], r[3]))

    def rel(p):
        return os.path.relpath(p, root) if os.path.abspath(p).startswith(root) else p

    long_rows = [r for r in rows if r[0] > args.min]
    if args.markdown:
        print("| lines | function | file |")
        print("|---|---|---|")
        for length, name, path, first, marked in long_rows:
            note = " (long-function)" if marked else ""
            print(f"| {length} | `{name}`{note} | `{rel(path)}:{first}` |")
    else:
        for length, name, path, first, marked in long_rows:
            note = "  [long-function]" if marked else ""
            print(f"{length:5d}  {name}  {rel(path)}:{first}{note}")
    over80 = sum(1 for r in rows if r[0] > 80)
    over150 = sum(1 for r in rows if r[0] > 150)
    print(f"\n{len(rows)} functions; {over80} over 80 lines, {over150} over 150 lines")
    if args.max is not None:
        bad = [r for r in rows if r[0] > args.max and not r[4]]
        if bad:
            print(f"function_lengths: {len(bad)} function(s) over {args.max} lines without a "
                  f"'{MARKER}' comment saying why:", file=sys.stderr)
            for length, name, path, first, _ in bad:
                print(f"  {rel(path)}:{first}: {name} ({length} lines)", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
