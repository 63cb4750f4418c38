#!/usr/bin/env python3
"""Fails when a crate's top-level modules, or the modules of one folder, import each other in
a cycle.

Each top-level module of a crate (`src/NAME.rs` with the files of `src/NAME/`) is a node; a
path `crate::OTHER…`, `super::OTHER` or a name the crate root re-exports from OTHER, outside
test code, is an edge. The same within each module folder (`src/P/`, module path P): its
child modules are the nodes, and `super::OTHER` from a child's file, `crate::P::OTHER` or a
name `P`'s `mod.rs` re-exports from OTHER are the edges. Test code is left out: everything
from the first `#[cfg(test)] mod` of a file on, and the files such a declaration brings in.
Prints every strongly connected group of more than one module and exits 1 if there is one.

Usage: module_cycles.py CRATE_SRC_DIR...
"""
import collections
import os
import re
import sys

TEST_MOD = re.compile(r"#\[cfg\(test\)\]\s*(?:pub(?:\([\w:]+\))?\s+)?mod\s+(\w+)")


def files_of(root, name):
    """The non-test sources of top-level module `name`."""
    out, skip = [], set()
    path = os.path.join(root, name + ".rs")
    if os.path.exists(path):
        out.append(path)
    folder = os.path.join(root, name)
    if os.path.isdir(folder):
        for dirpath, _, names in sorted(os.walk(folder)):
            out += [os.path.join(dirpath, f) for f in sorted(names) if f.endswith(".rs")]
    for p in out:
        for m in TEST_MOD.finditer(open(p).read()):
            base = p[:-3] if not p.endswith("mod.rs") else os.path.dirname(p)
            skip |= {os.path.join(base, m.group(1) + ".rs"), os.path.join(base, m.group(1))}
    return [p for p in out if not any(p == s or p.startswith(s + os.sep) for s in skip)]


def body(path):
    """The file's text before its first test module, comments dropped."""
    text = open(path).read()
    m = TEST_MOD.search(text)
    text = text if not m else text[: m.start()]
    return "\n".join(l for l in text.split("\n") if not l.strip().startswith("//"))


def edges_of(root, folder):
    """The child modules of module folder `folder` (the crate source `root` itself, or a
    folder under it) and their imports of each other."""
    top = folder == root
    heads = ["lib.rs", "main.rs"] if top else ["mod.rs"]
    heads = [os.path.join(folder, h) for h in heads] + ([] if top else [folder + ".rs"])
    heads = [h for h in heads if os.path.exists(h)]
    mods = sorted(
        {f[:-3] for f in os.listdir(folder) if f.endswith(".rs")} - {os.path.basename(h)[:-3] for h in heads if os.path.dirname(h) == folder}
        | {d for d in os.listdir(folder) if os.path.isdir(os.path.join(folder, d))}
    )
    reexports = []
    for h in heads:
        for mod, names in re.findall(r"pub(?:\([\w:]+\))? use (?:self::)?(\w+)::\{?([^;}]*)\}?;", body(h)):
            reexports += [(mod, n) for n in re.findall(r"\w+", names)]
    path = "" if top else "::".join(os.path.relpath(folder, root).split(os.sep)) + "::"
    group = r"(?:\{((?:[^{}]|\{[^{}]*\})*)\}|(\w+))"
    edges = collections.defaultdict(set)
    for m in mods:
        for file in files_of(folder, m):
            text = body(file)
            found = re.findall(r"crate::" + path + group, text)
            if os.path.dirname(file) == folder:
                found += re.findall(r"super::" + group, text)
            names = set()
            for many, one in found:
                names |= set(re.findall(r"\w+", many)) if many else {one}
            names |= {mod for mod, n in reexports if n in names}
            edges[m] |= {n for n in names if n in mods and n != m}
    return mods, edges


def folders(root):
    """The module folders under crate source `root`."""
    return sorted(d for d, _, _ in os.walk(root) if d != root)


def cycles(mods, edges):
    """Tarjan's strongly connected groups of more than one module."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                out.append(sorted(group))

    for m in mods:
        if m not in index:
            visit(m)
    return out


def main(roots):
    bad = 0
    n_folders = 0
    for root in roots:
        for where in [root] + folders(root):
            found = cycles(*edges_of(root, where))
            for group in found:
                print(f"{where}: modules import each other: {' ↔ '.join(group)}")
            bad += len(found)
        n_folders += len(folders(root))
    print(f"module cycles: {bad} in {len(roots)} crates and {n_folders} module folders")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
