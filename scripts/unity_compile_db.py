#!/usr/bin/env python3
"""unity_compile_db.py IN OUT: a unity build's compile database, one entry per source.

With CMAKE_UNITY_BUILD=ON, compile_commands.json names each batch (.../Unity/unity_N_cxx.cxx),
not the .cpp files it includes, and clang-tidy (scripts/lint tidy) is asked about .cpp files.
CMake puts files in one batch only when they build with the same flags, so each included file
gets its batch's command with the batch's path replaced by its own. Entries of files outside
any batch (SKIP_UNITY_BUILD_INCLUSION, single-file targets) are copied as they are.
"""
import json
import os
import re
import sys

UNITY = re.compile(r"[/\\]Unity[/\\]unity_\d+_(c|cxx)\.(c|cxx)$")


def sources(batch):
    with open(batch, encoding="utf-8") as f:
        return re.findall(r'^#include "([^"]+)"', f.read(), re.M)


def split(entries):
    out = []
    for e in entries:
        path = e["file"]
        if not os.path.isabs(path):
            path = os.path.join(e["directory"], path)
        if not UNITY.search(path):
            out.append(e)
            continue
        for src in sources(path):
            s = dict(e, file=src)
            if "command" in s:
                s["command"] = s["command"].replace(e["file"], src)
            if "arguments" in s:
                s["arguments"] = [src if a == e["file"] else a for a in s["arguments"]]
            out.append(s)
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: unity_compile_db.py BUILD/compile_commands.json OUT.json")
    with open(sys.argv[1], encoding="utf-8") as f:
        entries = json.load(f)
    os.makedirs(os.path.dirname(os.path.abspath(sys.argv[2])), exist_ok=True)
    with open(sys.argv[2], "w", encoding="utf-8") as f:
        json.dump(split(entries), f, indent=1)


if __name__ == "__main__":
    main()
