#!/usr/bin/env python3
"""List the include edges between core's folders (core/A includes core/B/...) and any cycles.

Usage: scripts/core-include-graph.py [--check]   (from the repository root)
--check exits 1 when the folder graph has a cycle (docs/architecture.md, "Core's folders").
"""
import os
import re
import sys

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "core")
include = re.compile(r'#\s*include\s+"core/([^/"]+)/')
edges = {}
for folder in sorted(os.listdir(root)):
    path = os.path.join(root, folder)
    if not os.path.isdir(path):
        continue
    edges.setdefault(folder, set())
    for dirpath, _, files in os.walk(path):
        for f in files:
            if not f.endswith((".h", ".cpp")):
                continue
            with open(os.path.join(dirpath, f), encoding="utf-8", errors="replace") as fh:
                for line in fh:
                    m = include.match(line.strip())
                    if m and m.group(1) != folder:
                        edges[folder].add(m.group(1))

for a in sorted(edges):
    print(f"{a} -> {', '.join(sorted(edges[a])) or '(nothing)'}")

# Cycles: strongly connected components with more than one folder (Tarjan).
index, low, stack, on, sccs, counter = {}, {}, [], set(), [], [0]
def visit(v):
    index[v] = low[v] = counter[0]; counter[0] += 1
    stack.append(v); on.add(v)
    for w in edges.get(v, ()):
        if w not in index:
            visit(w); low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop(); on.discard(w); comp.append(w)
            if w == v:
                break
        if len(comp) > 1:
            sccs.append(sorted(comp))
for v in sorted(edges):
    if v not in index:
        visit(v)
for c in sccs:
    print("cycle among: " + ", ".join(c))
if not sccs:
    print("no cycles")
if "--check" in sys.argv and sccs:
    sys.exit(1)
