#!/usr/bin/python3
"""The house's written rules, checked on the source tree (issue 29).

  house_check.py ROOT CHECK   runs one check (modules, readme, docs, tables, headers,
                              functions), exit 1 on a breach with one line per breach naming
                              the file
  house_check.py ROOT report  prints the figures: module edges, header include counts

A module is a folder directly under engine/ or baker/ holding sources (engine/io, generic file
I/O, includes no other); a header's count is the number of distinct project headers it reaches
through "..." includes, itself left out. A function's length is its lines from the first line of
its signature to its closing brace, blank and comment lines included.
"""
import os
import re
import sys

# A header may reach at most this many project headers (issue 29, measurement 3).
MAX_PROJECT_HEADERS = 15
# Headers over the limit today, with the count they may not exceed: the list only shrinks (a
# header that is back under the limit must leave it, so no room is kept for growth).
HEADERS_OVER_THE_LIMIT = {}
# No function in the programs and the bake pipeline runs longer than this many lines (issue 29,
# measurement 3): they read as a short list of steps.
MAX_FUNCTION_LINES = 100
FUNCTION_FOLDERS = ("engine/apps", "baker/apps", "baker/pipeline")
# A table cell longer than this is a paragraph in the wrong place.
MAX_TABLE_CELL = 600
# engine/ modules that are programs and may use the baker; every other engine module is a library
# that must not (the renderer reads bake folders through engine/bake_folder only).
ENGINE_PROGRAMS = {"engine/apps"}
# What a module of the baker may never reach: GL and the renderer.
GL_MODULES = {"engine/gl", "engine/render", "engine/apps"}
# Modules every other may use and that use no other (generic file I/O): one direction.
LEAF_MODULES = {"engine/io"}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def modules(root):
    found = []
    for top in ("engine", "baker"):
        for name in sorted(os.listdir(os.path.join(root, top))):
            path = os.path.join(root, top, name)
            if os.path.isdir(path) and any(
                    f.endswith((".h", ".cpp")) for f in os.listdir(path)):
                found.append(f"{top}/{name}")
    return found


def sources(root):
    for top in ("engine", "baker"):
        for folder, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith((".h", ".cpp")):
                    yield os.path.relpath(os.path.join(folder, f), root)


def include_graph(root):
    """file -> project files it includes (resolved as the compiler would: own folder, engine/,
    baker/)."""
    files = set(sources(root))
    graph = {}
    for f in files:
        with open(os.path.join(root, f), encoding="utf-8") as text:
            names = INCLUDE.findall(text.read())
        deps = []
        for n in names:
            for base in (os.path.dirname(f), "engine", "baker"):
                p = os.path.normpath(os.path.join(base, n))
                if p in files:
                    deps.append(p)
                    break
        graph[f] = deps
    return graph


def module_of(path):
    return "/".join(path.split("/")[:2])


def check_modules(root):
    graph = include_graph(root)
    breaches = []
    edges = set()
    for f, deps in graph.items():
        for d in deps:
            a, b = module_of(f), module_of(d)
            if a == b:
                continue
            edges.add((a, b))
            if a.startswith("engine/") and a not in ENGINE_PROGRAMS and b.startswith("baker/"):
                breaches.append(f"{f}: the engine library {a} includes the baker's {d}")
            if a.startswith("baker/") and b in GL_MODULES:
                breaches.append(f"{f}: the baker ({a}) includes {d} (GL or the renderer)")
            if a in LEAF_MODULES:
                breaches.append(f"{f}: {a} uses no other module, but includes {d}")
    # One direction: no cycle among modules.
    succ = {}
    for a, b in edges:
        succ.setdefault(a, set()).add(b)
    state = {}

    def visit(m, path):
        state[m] = 1
        for n in sorted(succ.get(m, ())):
            if state.get(n) == 1:
                cycle = path[path.index(n):] + [n] if n in path else [m, n]
                breaches.append("module include cycle: " + " -> ".join(cycle))
            elif n not in state:
                visit(n, path + [n])
        state[m] = 2

    for m in sorted(succ):
        if m not in state:
            visit(m, [m])
    return breaches


def readme_section(root, title):
    with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
        text = f.read()
    m = re.search(r"^## " + re.escape(title) + r"\n(.*?)(?=^## |\Z)", text, re.M | re.S)
    return m.group(1) if m else ""


def check_readme(root):
    layout = readme_section(root, "Layout")
    if not layout:
        return ["README.md: no '## Layout' section"]
    listed = set(re.findall(r"^\|\s*`([^`]+?)/?`\s*\|", layout, re.M))
    breaches = [f"README.md: the layout table does not list the module {m}"
                for m in modules(root) if m not in listed]
    breaches += [f"README.md: the layout table lists {p}, which is not a folder"
                 for p in sorted(listed) if not os.path.isdir(os.path.join(root, p))]
    return breaches


def check_docs(root):
    docs = readme_section(root, "Docs")
    if not docs:
        return ["README.md: no '## Docs' section"]
    listed = set(re.findall(r"`(docs/[^`]+\.md)`", docs))
    present = {f"docs/{f}" for f in os.listdir(os.path.join(root, "docs")) if f.endswith(".md")}
    breaches = [f"README.md: the Docs list does not name {d}" for d in sorted(present - listed)]
    breaches += [f"README.md: the Docs list names {d}, which does not exist"
                 for d in sorted(listed - present)]
    return breaches


def table_cells(line):
    # Split a Markdown table row on | that is neither escaped nor inside a code span.
    cells, cell, in_code, i = [], "", False, 0
    while i < len(line):
        c = line[i]
        if c == "\\" and i + 1 < len(line):
            cell += line[i:i + 2]
            i += 2
            continue
        if c == "`":
            in_code = not in_code
        if c == "|" and not in_code:
            cells.append(cell)
            cell = ""
        else:
            cell += c
        i += 1
    cells.append(cell)
    return cells[1:-1]


def check_tables(root):
    breaches = []
    paths = ["README.md"] + [os.path.join(d, f) for d, _, fs in os.walk(os.path.join(root, "docs"))
                             for f in sorted(fs) if f.endswith(".md")]
    for p in paths:
        full = p if os.path.isabs(p) else os.path.join(root, p)
        with open(full, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                if not line.startswith("|"):
                    continue
                for cell in table_cells(line.rstrip("\n")):
                    if len(cell) > MAX_TABLE_CELL:
                        breaches.append(f"{os.path.relpath(full, root)}:{number}: a table cell of "
                                        f"{len(cell)} characters (at most {MAX_TABLE_CELL})")
    return breaches


def header_counts(root):
    graph = include_graph(root)
    memo = {}

    def reach(f):
        if f not in memo:
            memo[f] = set()  # a cycle contributes nothing twice
            seen = set()
            for d in graph[f]:
                seen.add(d)
                seen |= reach(d)
            seen.discard(f)
            memo[f] = seen
        return memo[f]

    return {f: len(reach(f)) for f in graph if f.endswith(".h")}


def check_headers(root):
    breaches = []
    counts = header_counts(root)
    for f, n in sorted(counts.items()):
        allowed = HEADERS_OVER_THE_LIMIT.get(f, MAX_PROJECT_HEADERS)
        if n > allowed:
            breaches.append(f"{f}: includes {n} project headers (at most {allowed})")
    for f, n in sorted(HEADERS_OVER_THE_LIMIT.items()):
        if f not in counts:
            breaches.append(f"house_check.py: {f} is listed over the limit but does not exist")
        elif counts[f] <= MAX_PROJECT_HEADERS:
            breaches.append(f"house_check.py: {f} is back under the limit ({counts[f]}): "
                            "take it off HEADERS_OVER_THE_LIMIT")
    return breaches


# C++ functions, found by their braces (no parser): a '{' outside any function body whose text
# since the last ';', '{' or '}' holds a ')' opens a function, unless that text starts a
# namespace, class, struct, enum or union. Lambdas and local classes count as part of the
# function they are in.
def strip_code(text):
    """Comments, string and character literals and preprocessor lines blanked (newlines kept)."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            # a preprocessor line, with its continuations
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n"); i += 2; continue
                out.append(" "); i += 1
            continue
        if c == "\n":
            out.append(c); i += 1; at_line_start = True; continue
        if c in " \t":
            out.append(c); i += 1; continue
        at_line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" "); i += 1
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end])); i = end; continue
        m = re.match(r'R"([^(\s]*)\(', text[i:i + 20])
        if m:
            end = text.find(")" + m.group(1) + '"', i)
            end = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end])); i = end; continue
        if c in "\"'":
            # a digit separator (1'000) is no character literal
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(" "); i += 1; continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(re.sub(r"[^\n]", " ", text[i:j + 1])); i = j + 1; continue
        out.append(c); i += 1
    return "".join(out)

def functions(text):
    """(name, first line, last line) of each function body not inside another function."""
    code = strip_code(text)
    found = []
    depth = 0
    inside = None  # depth at which the current function's body opened
    header_start = 0
    for i, c in enumerate(code):
        if c == "{":
            if inside is None:
                header = code[header_start:i]
                words = header.split()
                if ")" in header and (not words or words[0] not in (
                        "namespace", "class", "struct", "enum", "union", "extern")):
                    head = re.sub(r"^\s*((public|private|protected)\s*:\s*)*", "", header)
                    first = i - len(header) + (len(header) - len(head))
                    first += len(head) - len(head.lstrip())
                    name = re.findall(r"([~\w:]+)\s*\(", head)
                    found.append([name[0] if name else "?", code.count("\n", 0, first) + 1, None])
                    inside = depth
            depth += 1
            header_start = i + 1
        elif c == "}":
            depth -= 1
            if inside is not None and depth == inside:
                found[-1][2] = code.count("\n", 0, i) + 1
                inside = None
            header_start = i + 1
        elif c == ";" and inside is None:
            header_start = i + 1
    return [tuple(f) for f in found if f[2] is not None]


def check_functions(root):
    breaches = []
    for folder in FUNCTION_FOLDERS:
        for directory, _, files in os.walk(os.path.join(root, folder)):
            for f in sorted(files):
                if not f.endswith((".h", ".cpp")):
                    continue
                path = os.path.join(directory, f)
                with open(path, encoding="utf-8") as text:
                    found = functions(text.read())
                for name, first, last in found:
                    if last - first + 1 > MAX_FUNCTION_LINES:
                        breaches.append(f"{os.path.relpath(path, root)}:{first}: {name} runs "
                                        f"{last - first + 1} lines (at most "
                                        f"{MAX_FUNCTION_LINES})")
    return breaches


def report(root):
    graph = include_graph(root)
    edges = sorted({(module_of(f), module_of(d)) for f, ds in graph.items() for d in ds
                    if module_of(f) != module_of(d)})
    print(f"{len(modules(root))} modules, {len(edges)} module edges")
    for a, b in edges:
        print(f"  {a} -> {b}")
    counts = header_counts(root)
    print("headers by project headers reached (largest 20):")
    for f, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))[:20]:
        print(f"  {n:3d} {f}")
    return []


CHECKS = {"modules": check_modules, "readme": check_readme, "docs": check_docs,
          "tables": check_tables, "headers": check_headers, "functions": check_functions,
          "report": report}


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in CHECKS:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    root = sys.argv[1]
    breaches = CHECKS[sys.argv[2]](root)
    for b in breaches:
        print(b)
    if sys.argv[2] != "report":
        print(f"house_check {sys.argv[2]}: {len(breaches)} breaches")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main())
