"""Every command shown in README.md and docs/*.md runs as written.

Each ```sh block's lines (continuations joined) run in order, per document, with bash in a
scratch folder that holds links to the repository's examples/, scripts/, python/ and build
folder, `deploydyn` on PATH and the package on PYTHONPATH, so the documents' relative paths work
and nothing is written into the repository. A line fails the test when it exits non-zero.
Not run:
  - usage lines, which show the syntax rather than a command: they hold an optional part
    `[...]`, an alternative `a|b` or an upper-case placeholder (MODEL, DIR, RESULT_DIR ...);
  - the commands of NOT_RUN, each with its reason; the test also fails when one of them is no
    longer in the documents, so that the list does not outlive them.
The tutorial's ```python blocks run too (docs/tutorial.md promises that they do).
"""
import os
import pathlib
import re
import subprocess

import pytest

from conftest import CLI, SOURCE_DIR

DOCUMENTS = [SOURCE_DIR / "README.md"] + sorted((SOURCE_DIR / "docs").glob("*.md"))
PYTHON_BLOCKS_RUN = {"tutorial.md"}

# Command (its beginning) → why a test does not run it.
NOT_RUN = {
    "make demo": "the demo itself: minutes of runs and figures; CI's make test builds what it uses",
    "make test": "the test suite that runs this test",
    "cmake --install": "installs into /opt; tests/install/ installs and consumes the package",
    "/usr/bin/python3 scripts/paper_study.py": "regenerates examples/paper/variants/ in the "
                                               "repository and runs 40 variants (minutes)",
    "/usr/bin/python3 scripts/boom_demo.py": "make demo runs it (three spring-driven deployments and figures)",
}

# Upper-case words (MODEL, DIR, RESULT_DIR, PATH=VALUE ...), or one letter as an option's value
# (--units N, --at T).
PLACEHOLDER = re.compile(r"\b[A-Z][A-Z_]{2,}\b|\bPATH=VALUE\b|--[\w-]+ [A-Z]\b")


def blocks(document, language):
    text = document.read_text(encoding="utf-8")
    for match in re.finditer(rf"^```{language}\n(.*?)^```", text, re.S | re.M):
        line = text[:match.start()].count("\n") + 1
        yield line, match.group(1)


def commands(document):
    """(line number, command) of the document's shell blocks, continuations joined."""
    out = []
    for line, body in blocks(document, "(?:sh|bash)"):
        pending, start = "", None
        for k, text in enumerate(body.splitlines()):
            if start is None:
                start = line + 1 + k
            if text.rstrip().endswith("\\"):
                pending += text.rstrip()[:-1] + " "
                continue
            command = (pending + text).strip()
            pending, start_line, start = "", start, None
            if command and not command.startswith("#"):
                out.append((start_line, command))
    return out


def without_comment(command):
    """The command without a trailing `# comment` (outside quotes)."""
    quote = None
    for i, c in enumerate(command):
        if c in "'\"" and quote in (None, c):
            quote = None if quote == c else c
        elif c == "#" and quote is None and (i == 0 or command[i - 1].isspace()):
            return command[:i].rstrip()
    return command


def is_usage(command):
    bare = re.sub(r"'[^']*'|\"[^\"]*\"", "", command)  # quoted text may hold anything
    return "[" in bare or re.search(r"\w\|\w", bare) is not None or PLACEHOLDER.search(bare) is not None


def not_run_reason(command):
    for prefix, reason in NOT_RUN.items():
        if command.startswith(prefix):
            return reason
    return None


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    root = tmp_path_factory.mktemp("docs")
    for name in ("examples", "scripts", "python"):
        (root / name).symlink_to(SOURCE_DIR / name)
    build = pathlib.Path(CLI).resolve().parent
    (root / "build").mkdir()
    (root / "build" / "release").symlink_to(build)
    return root, build


def environment(build):
    env = dict(os.environ)  # with the sanitizer build's LD_PRELOAD: its Python module needs it
    env["PATH"] = f"{build}:{env['PATH']}"
    env["PYTHONPATH"] = str(build / "python")
    return env


@pytest.mark.parametrize("document", DOCUMENTS, ids=lambda d: d.name)
def test_the_commands_of_a_document_run(document, scratch, tmp_path):
    root, build = scratch
    folder = tmp_path / "work"
    folder.mkdir()
    for name in ("examples", "scripts", "python", "build"):
        (folder / name).symlink_to(root / name)
    ran = 0
    for line, command in commands(document):
        command = without_comment(command)
        if is_usage(command) or not_run_reason(command) is not None:
            continue
        done = subprocess.run(["bash", "-e", "-c", command], cwd=folder, env=environment(build),
                              capture_output=True, text=True, timeout=240)
        assert done.returncode == 0, (f"{document.name}:{line}: `{command}` exited with "
                                      f"{done.returncode}:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")
        ran += 1
    if document.name in PYTHON_BLOCKS_RUN:
        for line, body in blocks(document, "python"):
            done = subprocess.run(["/usr/bin/python3", "-c", body], cwd=folder, env=environment(build),
                                  capture_output=True, text=True, timeout=240)
            assert done.returncode == 0, f"{document.name}:{line}: the Python block failed:\n{done.stderr[-3000:]}"
            ran += 1
    shown = [c for _, c in commands(document)]
    assert ran > 0 or not shown or all(is_usage(without_comment(c)) or not_run_reason(without_comment(c))
                                       for c in shown)


def test_every_command_not_run_is_still_shown():
    shown = [without_comment(c) for d in DOCUMENTS for _, c in commands(d)]
    for prefix in NOT_RUN:
        assert any(c.startswith(prefix) for c in shown), f"NOT_RUN lists {prefix!r}, which no document shows"


def test_usage_lines_are_told_from_commands():
    assert is_usage("deploydyn run MODEL [--out DIR]")
    assert is_usage("deploydyn generate roof --units N")
    assert is_usage("deploydyn report RESULT_DIR [--out FILE]")
    assert is_usage("deploydyn check MODEL")
    assert not is_usage("deploydyn check examples/paper/general.yaml --set supports.1.node=C")
    assert not is_usage("deploydyn run examples/paper/general.yaml --out results/hot --set thermal.dT=130")
    assert not is_usage("/usr/bin/python3 scripts/deploydyn_plot.py a b --label \"ΔT = +30 °C\"")
    assert without_comment("make demo   # installs ... # twice") == "make demo"
    assert without_comment("echo '#not a comment'") == "echo '#not a comment'"
