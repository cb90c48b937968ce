#!/usr/bin/env python3
"""Checks the documentation as a reader meets it (ctest: Docs.FrontDoorAndLinks):
- README.md stays a front door: under 300 lines;
- every relative link and image in README.md and docs/*.md resolves to a
  file in the tree, and every #anchor to a heading of that file;
- the tree cites papers by the keys of docs/references.md, never by the
  names of files or tracker entries outside the repository (the pattern
  `stale` below), which a reader of the repository cannot follow;
- the README's command table lists exactly the program's commands (the
  table in tools/dermis/main.cpp that `dermis --help` prints), and its layer
  list exactly the folders of engine/;
- every path of the tree the docs name (`tools/x.py`, `engine/plan/Y`, a
  stem standing for its .h and .cpp) exists;
- every test the docs name (`Suite.Name`, wildcards allowed) and every
  `ctest -R PATTERN` they give matches a test of tests/ (a GoogleTest TEST
  or an add_test NAME), so that a renamed or removed test leaves no
  pointer to nothing behind;
- with the program given (check_docs.py ROOT [DERMIS]), every default the
  docs state for an option ("`--frames N` ... (default 10)", or a table's
  "default" column) is one that some command's --help states for it.
Prints every problem, exits 1 if there is one."""
import re
import subprocess
import sys
from pathlib import Path

root = Path(sys.argv[1]).resolve()
problems = []

readme_lines = (root / "README.md").read_text(encoding="utf-8").count("\n")
if readme_lines >= 300:
    problems.append(f"README.md: {readme_lines} lines; the front door stays under 300 (move detail to docs/)")


def anchors(path):
    """GitHub-style heading anchors of a Markdown file."""
    result = set()
    for line in path.read_text(encoding="utf-8").splitlines():
        match = re.match(r"#+\s+(.*)", line)
        if match:
            text = re.sub(r"[`*_]", "", match.group(1)).strip().lower()
            result.add(re.sub(r"[^\w\- ]", "", text).replace(" ", "-"))
    return result


# Every page a reader meets: the README and the chapters and results it links.
pages = [root / "README.md", *sorted((root / "docs").glob("*.md")), *sorted((root / "docs" / "results").glob("*.md"))]
link = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
for page in pages:
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    for target in link.findall(text):
        if re.match(r"[a-z]+:", target):
            continue
        file_part, _, anchor = target.partition("#")
        destination = (page.parent / file_part).resolve() if file_part else page
        if not destination.exists():
            problems.append(f"{page.relative_to(root)}: link to {target}: no such file")
        elif anchor and destination.suffix == ".md" and anchor not in anchors(destination):
            problems.append(f"{page.relative_to(root)}: link to {target}: no heading with that anchor")

stale = re.compile(r"[Ss]eed 00[0-9]|DESIGN\.md|\bissue [0-9]")
tracked = subprocess.run(["git", "-C", str(root), "ls-files"], capture_output=True, text=True, check=True).stdout.split()
for name in tracked:
    path = root / name
    if path.suffix in {".png", ".exr", ".jpg", ".glb", ".bin"} or not path.is_file():
        continue
    for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
        if stale.search(line):
            problems.append(f"{name}:{number}: cites '{stale.search(line).group(0)}', which the repository does not hold; "
                            "cite by the keys of docs/references.md")

readme = (root / "README.md").read_text(encoding="utf-8")
program_commands = re.findall(r'^\s*\{"([a-z-]+)", "', (root / "tools/dermis/main.cpp").read_text(encoding="utf-8"),
                              flags=re.M)
readme_commands = re.findall(r"^\| `([a-z-]+)` \|", readme.split("## Using `dermis`")[1].split("\n## ")[0], flags=re.M)
if not program_commands:
    problems.append("tools/dermis/main.cpp: no command table found")
if sorted(readme_commands) != sorted(program_commands):
    problems.append(f"README.md: the command table lists {sorted(readme_commands)}; the program has "
                    f"{sorted(program_commands)}")
engine_layers = sorted(p.name for p in (root / "engine").iterdir() if p.is_dir())
readme_layers = sorted(re.findall(r"^engine/([a-z]+)/ ", readme, flags=re.M))
if readme_layers != engine_layers:
    problems.append(f"README.md: the layer list has {readme_layers}; engine/ has {engine_layers}")


# Paths of the tree the docs name must exist; a stem stands for its .h and .cpp;
# a name with a placeholder (<Name>, *) is a pattern, not a path.
for page in pages:
    text = page.read_text(encoding="utf-8")
    for named in sorted(set(re.findall(r"(?<![\w/.-])((?:content|tools|docs|shaders|engine|tests|\.ci)/[\w./<>*-]+)", text))):
        named = named.rstrip(".,:;")
        if re.search(r"[<>*]", named):
            continue
        if not any((root / (named + suffix)).exists() for suffix in ("", ".h", ".cpp")):
            problems.append(f"{page.relative_to(root)}: names {named}, which is not in the tree")


# Tests the docs cite must exist: GoogleTest names (TEST, TEST_F, TEST_P) and
# ctest's own (add_test NAME).
import fnmatch
test_names = set()
for source in sorted((root / "tests").rglob("*.cpp")):
    for suite, name in re.findall(r"\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)", source.read_text(encoding="utf-8")):
        test_names.add(f"{suite}.{name}")
test_names.update(re.findall(r"add_test\(NAME ([\w.]+)", (root / "tests/CMakeLists.txt").read_text(encoding="utf-8")))
for page in pages:
    text = page.read_text(encoding="utf-8")
    # `Suite.Name`: a capitalised suite that is not a placeholder in capitals (`NAME.R`).
    for cited in sorted(set(re.findall(r"`([A-Z][A-Za-z0-9]*[a-z][A-Za-z0-9]*\.[A-Z*][\w*]*)`", text))):
        if not any(fnmatch.fnmatchcase(test, cited) for test in test_names):
            problems.append(f"{page.relative_to(root)}: names the test `{cited}`, which no test in tests/ is")
    for single, double, bare in re.findall(r"ctest [^`\n]*?-R\s+(?:'([^']+)'|\"([^\"]+)\"|([^\s`'\"\\)]+))", text):
        pattern = single or double or bare
        if not any(re.search(pattern, test) for test in test_names):
            problems.append(f"{page.relative_to(root)}: `ctest -R {pattern}` matches no test in tests/")


# The chapter that documents each command's options (README.md documents them all).
COMMAND_PAGES = {"cli.md": "render", "reference.md": "reference", "bench.md": "bench", "quality.md": "tune",
                 "stress.md": "stress", "texture-space.md": "compare", "lean.md": "bake-lean", "viewer.md": "view",
                 "shards.md": "merge"}

# The README's examples of one command each write their own file: a reader
# who runs them one after another keeps every result.
for command in ("render", "compare", "bench", "reference", "tune"):
    outputs = {}
    for line in re.findall(r"^build/dermis " + command + r" .*$", readme, flags=re.M):
        match = re.search(r"--out[ =](\S+)", line)
        target = match.group(1) if match else "out/<scene name>.png (the default)"
        if target in outputs:
            problems.append(f"README.md: two `dermis {command}` examples write {target}:\n  {outputs[target]}\n  {line}")
        outputs[target] = line


def help_defaults(program):
    """{command: {option: default}}: "default X" in the lines of each option of each command's --help."""
    defaults = {}
    for command in program_commands:
        text = subprocess.run([program, command, "--help"], capture_output=True, text=True).stdout
        option = None
        for line in text.splitlines():
            start = re.match(r"^  (--[a-z][\w-]*)", line)
            if start:
                option = start.group(1)
            elif not line.startswith("     "):
                option = None
            for value in re.findall(r"\bdefault:? ([^),;]+)", line) if option else []:
                defaults.setdefault(command, {})[option] = normalise(value)
    return defaults


def normalise(value):
    return value.strip().strip("`*").rstrip(".").split(",")[0].split(":")[0].strip().strip("`").lower()


def documented_defaults():
    """(page, option, default) for each default the docs state next to an option: in a table
    row whose table has a "default" column, or in prose ("`--opt N` (..., default X)")."""
    found = []
    inline = r"`[^`(]{0,40}\((?:[^()]*?\b)?default:? ([^),;]+)"
    for page in [root / "README.md", *sorted((root / "docs").glob("*.md"))]:
        text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
        default_column = None
        paragraph = []
        for line in text.splitlines() + [""]:
            if not line.startswith("|"):
                default_column = None
                if line.strip():
                    paragraph.append(line.strip())
                    continue
                joined = " ".join(paragraph)
                paragraph = []
                for option in set(re.findall(r"`(--[a-z][\w-]*)", joined)):
                    for value in re.findall(re.escape(option) + r"(?![\w-])[^`]*" + inline, joined):
                        found.append((page, option, normalise(value)))
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if any(c.lower() == "default" for c in cells):
                default_column = [c.lower() for c in cells].index("default")
                continue
            for option in set(re.findall(r"`(--[a-z][\w-]*)", line)):
                if default_column is not None and len(cells) > default_column and cells[0].startswith(f"`{option}"):
                    found.append((page, option, normalise(cells[default_column])))
                for value in re.findall(re.escape(option) + r"(?![\w-])[^`]*" + inline, line):
                    found.append((page, option, normalise(value)))
    return found


if len(sys.argv) > 2:
    known = help_defaults(sys.argv[2])
    for page, option, value in documented_defaults():
        command = COMMAND_PAGES.get(page.name)
        stated = ({known[command][option]} if option in known.get(command, {}) else set()) if command else \
            {options[option] for options in known.values() if option in options}
        if value in ("required",) or not stated or value in stated:
            continue
        problems.append(f"{page.relative_to(root)}: {option}: the docs say the default is {value}; "
                        f"`dermis {command or '...'} --help` says {' or '.join(sorted(stated))}")
else:
    print("no program given: the documented defaults are not checked")

for problem in problems:
    print(problem)
print(f"docs: {len(problems)} problems")
sys.exit(1 if problems else 0)
