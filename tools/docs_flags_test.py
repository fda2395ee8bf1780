#!/usr/bin/python3
"""ctest program_docs_flags: the program's commands and flags in the docs exist.

Usage: docs_flags_test.py MANYWORLDS SOURCE_DIR

Extracts every `manyworlds <command> --flag ...` (also as build/tools/manyworlds
or ./build/tools/manyworlds) and `./scripts/run --flag ...` (= `manyworlds
run`) from the code of README.md and docs/*.md (fenced blocks and inline code
spans) and fails, naming the file, line, command and flag, when
  - `manyworlds --help` has no section for the command, or does not list the
    flag in that command's section, or
  - the program refuses the flag as an unknown option. It is asked without
    doing anything: `manyworlds COMMAND FLAG x --docs-check-no-such-option`
    always ends in a usage error (the flag's value, a stray argument or the
    unknown last option), and only the flag's own refusal names the flag.
"""

import glob
import os
import re
import subprocess
import sys

MANYWORLDS, SOURCE = sys.argv[1], sys.argv[2]

PROGRAM = re.compile(r"^(\./)?(build/tools/)?manyworlds$")
SCRIPT_RUN = re.compile(r"^(\./)?scripts/run$")
# Tokens after which a new command starts in a shell line.
SEPARATORS = {"&&", "||", ";", "|", "$", "time", "exec", "then", "do"}


def help_sections():
    """{command: set of flags} from `manyworlds --help`."""
    text = subprocess.run([MANYWORLDS, "--help"], capture_output=True, text=True,
                          check=True).stdout
    sections, current = {}, None
    for line in text.splitlines():
        start = re.match(r"^  manyworlds ([a-z]+)", line)
        if start:
            current = start.group(1)
            sections.setdefault(current, set())
        elif not line.startswith(" "):
            current = None  # "usage:", "exit codes:" and the like
        if current:
            sections[current].update(re.findall(r"--[a-z][a-z-]*", line))
    return sections


def code_segments(path):
    """(line number, code text) of every fenced block line (with `\\`
    continuations joined and # comments dropped) and inline code span."""
    segments, fenced, pending, pending_line = [], False, "", 0
    with open(path, encoding="utf-8") as file:
        for number, line in enumerate(file, 1):
            if line.lstrip().startswith("```"):
                fenced = not fenced
                continue
            if fenced:
                code = re.sub(r"(^|\s)#.*", "", line.rstrip("\n"))
                if not pending:
                    pending_line = number
                if code.rstrip().endswith("\\"):
                    pending += code.rstrip()[:-1] + " "
                    continue
                segments.append((pending_line, pending + code))
                pending = ""
            else:
                segments.extend((number, span) for span in re.findall(r"`([^`\n]+)`", line))
    return segments


def invocations(segment):
    """(command, [flags]) of every program or scripts/run call in a segment."""
    tokens = segment.split()
    found = []
    for i, token in enumerate(tokens):
        if i > 0 and tokens[i - 1] not in SEPARATORS:
            continue
        if SCRIPT_RUN.match(token):
            command, rest = "run", tokens[i + 1:]
        elif PROGRAM.match(token) and i + 1 < len(tokens) and re.match(r"^[a-z]+$",
                                                                        tokens[i + 1]):
            command, rest = tokens[i + 1], tokens[i + 2:]
        else:
            continue
        flags = []
        for word in rest:
            if word in SEPARATORS or word.startswith((">", "<", "2>")):
                break
            flag = re.match(r"^\[?(--[a-z][a-z-]*)", word)
            if flag:
                flags.append(flag.group(1))
        found.append((command, flags))
    return found


def refused(command, flag):
    result = subprocess.run([MANYWORLDS, command, flag, "x", "--docs-check-no-such-option"],
                            capture_output=True, text=True, timeout=30)
    return f"unknown option '{flag}'" in result.stderr or "unknown command" in result.stderr


def main():
    sections = help_sections()
    if not {"run", "plan", "scenes", "sweep"} <= sections.keys():
        print(f"docs_flags_test: --help has sections {sorted(sections)} only", file=sys.stderr)
        return 1
    paths = [os.path.join(SOURCE, "README.md")] + sorted(glob.glob(os.path.join(SOURCE, "docs",
                                                                                "*.md")))
    problems, checked = [], 0
    for path in paths:
        where_file = os.path.relpath(path, SOURCE)
        for line, segment in code_segments(path):
            for command, flags in invocations(segment):
                checked += 1
                where = f"{where_file}:{line}"
                if command not in sections:
                    problems.append(f"{where}: command '{command}' is not in manyworlds --help")
                    continue
                for flag in flags:
                    checked += 1
                    if flag == "--help":
                        continue
                    if flag not in sections[command]:
                        problems.append(f"{where}: '{command} {flag}' is not listed under "
                                        f"'manyworlds {command}' in manyworlds --help")
                    if refused(command, flag):
                        problems.append(f"{where}: 'manyworlds {command}' refuses {flag}")
    # A broken extractor must not pass by finding nothing.
    if checked < 20:
        problems.append(f"only {checked} commands and flags found in the docs: extractor broken?")
    for problem in problems:
        print(f"docs_flags_test: {problem}", file=sys.stderr)
    print(f"docs_flags_test: {checked} commands and flags checked, {len(problems)} problems")
    return 1 if problems else 0


sys.exit(main())
