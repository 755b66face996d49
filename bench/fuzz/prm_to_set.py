#!/usr/bin/python3
"""Turn .prm files into seeds of the --set harness (bench/fuzz/fuzz_set.cc):
every `set Entry = value` of a file becomes one line
`Subsection/.../Entry=value`, in the file's order (comments dropped,
continuation lines joined), so that applying the lines with `hati --set` to
the defaults gives the parameters of the file.

Usage: prm_to_set.py OUTPUT_DIR FILE.prm...  (writes OUTPUT_DIR/<name>.set)"""
import os
import re
import sys


def assignments(text):
    """The `path=value` lines of the .prm text."""
    lines, joined = [], ""
    for raw in text.splitlines():
        # a comment starts at a '#' not escaped by a backslash
        line = re.sub(r"(?<!\\)#.*", "", raw).replace("\\#", "#").rstrip()
        if line.endswith("\\"):
            joined += line[:-1] + " "
            continue
        lines.append(joined + line)
        joined = ""
    if joined:
        lines.append(joined)
    path, out = [], []
    for line in lines:
        words = line.strip()
        if words.startswith("subsection "):
            path.append(words[len("subsection "):].strip())
        elif words == "end":
            path.pop()
        elif words.startswith("set "):
            name, _, value = words[len("set "):].partition("=")
            out.append("/".join(path + [name.strip()]) + "=" + value.strip())
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    os.makedirs(sys.argv[1], exist_ok=True)
    for prm in sys.argv[2:]:
        with open(prm, encoding="utf-8-sig") as f:
            lines = assignments(f.read())
        name = os.path.splitext(os.path.basename(prm))[0] + ".set"
        with open(os.path.join(sys.argv[1], name), "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
