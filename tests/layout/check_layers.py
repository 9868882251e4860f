#!/usr/bin/env python3
"""The include rules of the source tree, checked on every test run.

- Layers point one way: engine/ includes neither api/ nor server/ nor cli/; api/ includes neither
  server/ nor cli/; server/ and cli/ do not include each other.
- Inside engine/ and server/ the folders include each other without a cycle.
- Inside server/ nothing below the root includes a root header but app.hpp and options.hpp (what the
  process composes), and nothing outside routes/ includes routes/.
- server/ itself holds at most 12 source files and no folder of it more than 25 .cpp files.

Prints each broken rule and exits 1, or prints a summary and exits 0.
"""
import pathlib
import re
import sys
from collections import defaultdict

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
LAYERS = {"engine": set(), "api": {"engine"}, "server": {"api", "engine"}, "cli": {"api", "engine"}}
ROOT_HEADERS_ALLOWED_BELOW = {"server/app.hpp", "server/options.hpp"}
MAX_ROOT_SOURCES, MAX_FOLDER_CPP = 12, 25


def sources(top):
    return sorted(p for p in (ROOT / top).rglob("*") if p.suffix in (".cpp", ".hpp"))


def includes(path):
    return [i for i in INCLUDE.findall(path.read_text(errors="replace")) if "/" in i]


def folder_of(rel, top):
    """server/http/router.hpp -> "http"; server/app.hpp -> "" (the root)."""
    parts = pathlib.PurePosixPath(rel).parts
    return parts[1] if len(parts) > 2 and parts[0] == top else ""


def find_cycle(graph):
    state, stack = {}, []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def main():
    problems = []
    for top, allowed in LAYERS.items():
        for path in sources(top):
            rel = path.relative_to(ROOT).as_posix()
            for inc in includes(path):
                layer = inc.split("/")[0]
                if layer in LAYERS and layer != top and layer not in allowed:
                    problems.append(f"{rel} includes {inc}: {top}/ may not include {layer}/")

    for top in ("engine", "server"):
        graph = defaultdict(set)
        for path in sources(top):
            rel = path.relative_to(ROOT).as_posix()
            here = folder_of(rel, top)
            graph[here]
            for inc in includes(path):
                if not inc.startswith(top + "/"):
                    continue
                there = folder_of(inc, top)
                if top == "server" and here != "" and there == "" and inc not in ROOT_HEADERS_ALLOWED_BELOW:
                    problems.append(f"{rel} includes {inc}: below the root only app.hpp and options.hpp")
                if top == "server" and there == "routes" and here not in ("", "routes"):
                    problems.append(f"{rel} includes {inc}: only the root and routes/ include routes/")
                if there != here and not (top == "server" and there == ""):
                    graph[here].add(there)
        cycle = find_cycle(graph)
        if cycle:
            problems.append(f"{top}/ folders include each other in a cycle: {' -> '.join(cycle)}")

    root_sources = [p for p in (ROOT / "server").iterdir() if p.suffix in (".cpp", ".hpp")]
    if len(root_sources) > MAX_ROOT_SOURCES:
        problems.append(f"server/ holds {len(root_sources)} source files (at most {MAX_ROOT_SOURCES})")
    for folder in (p for p in (ROOT / "server").iterdir() if p.is_dir()):
        count = len(list(folder.glob("*.cpp")))
        if count > MAX_FOLDER_CPP:
            problems.append(f"server/{folder.name}/ holds {count} .cpp files (at most {MAX_FOLDER_CPP})")

    for problem in problems:
        print(problem)
    if problems:
        return 1
    print(f"layers, folder cycles and folder sizes: 0 problems ({len(root_sources)} source files in server/)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
