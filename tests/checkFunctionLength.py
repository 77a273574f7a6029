#!/usr/bin/env python3
"""Functions of one idea: no function body under the given folders is longer than the
limit (lines from its opening to its closing brace). Prints the longest functions and
every one over the limit.

Usage: checkFunctionLength.py <limit> <folder>...

A small lexer, not a C++ parser: comments, string and character literals are blanked,
then a brace opens a function body when the text before it (since the last ';', '{' or
'}') ends in a parameter list and is not a control statement, a lambda or a type; bodies
nested in a function (lambdas, blocks) count as part of it.
"""
import os
import re
import sys

CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else)\b\s*(\(|$)")
TYPE = re.compile(r"\b(namespace|class|struct|enum|union)\b")
FUNCTION_HEAD = re.compile(
    r"\)\s*(const)?\s*(noexcept)?\s*(override|final)?\s*(->\s*[^{;]*)?\s*(:[^{;]*)?$", re.S)


def blank_literals_and_comments(text):
    """The text with comments and literals replaced by spaces (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def function_lengths(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = blank_literals_and_comments(f.read())
    text = re.sub(r"^\s*#.*$", "", text, flags=re.M)  # preprocessor lines
    stack, found = [], []
    line, head_start = 1, 0
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        elif c == "{":
            head = text[head_start:i].strip()
            in_function = any(kind == "function" for kind, _, _ in stack)
            is_function = (
                not in_function
                and FUNCTION_HEAD.search(head)
                and not CONTROL.search(head)
                and not TYPE.search(head.split("(")[0])
                and not re.search(r"\]\s*(\([^)]*\))?\s*(mutable)?\s*(->[^{]*)?$", head)
            )
            name = ""
            if is_function:
                names = re.findall(r"([\w:~]+)\s*\(", head)
                name = names[0] if names else "?"
            stack.append(("function" if is_function else "block", line, name))
            head_start = i + 1
        elif c == "}":
            if stack:
                kind, start, name = stack.pop()
                if kind == "function":
                    found.append((line - start + 1, path, start, name))
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
    return found


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    limit = int(sys.argv[1])
    functions = []
    for folder in sys.argv[2:]:
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                if name.endswith((".cpp", ".hpp", ".C", ".H")):
                    functions += function_lengths(os.path.join(root, name))
    functions.sort(reverse=True)
    print(f"{len(functions)} functions; the longest:")
    for length, path, start, name in functions[:5]:
        print(f"  {length:4d} lines  {path}:{start}  {name}")
    over = [f for f in functions if f[0] > limit]
    for length, path, start, name in over:
        print(f"FAILED: {path}:{start} {name} is {length} lines (limit {limit}): split it")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
