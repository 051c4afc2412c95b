"""Every ``cityshade`` command line written in the README and the user guide parses: its
command exists and each option is one the command has, with its value (a renamed or removed
option fails here, not in a reader's terminal)."""
from __future__ import annotations

import re
import shlex

import click
import pytest
from conftest import REPO

from cityshade.cli.main import cli

DOCS = ("README.md", "docs/GUIDE.md", "sample_data/demo.sh")


def _command_lines(text: str, script: bool = False) -> list[str]:
    """``cityshade …`` commands of the ``sh`` code blocks (of the whole text for a script):
    continuation lines joined, ``&&`` chains split, comments dropped; a script's variables
    stand for file names."""
    out = []
    blocks = [text] if script else re.findall(r"```sh\n(.*?)```", text, flags=re.S)
    for block in blocks:
        if script:
            block = re.sub(r"\$\{?(\w+)\}?", r"\1", block.replace('"', ""))
        joined = re.sub(r"\\\n\s*", " ", block)
        for line in joined.splitlines():
            for part in line.split("&&"):
                part = part.split(" #")[0].strip()
                if part.startswith("cityshade "):
                    out.append(part)
    return out


def _cases():
    for name in DOCS:
        path = REPO / name
        for line in _command_lines(path.read_text(encoding="utf-8"), name.endswith(".sh")):
            yield pytest.param(line, id=f"{name}:{line[:60]}")


def test_the_docs_have_commands():
    assert len(list(_cases())) >= 10


@pytest.mark.parametrize("line", list(_cases()))
def test_a_documented_command_parses(line):
    args = shlex.split(line)[1:]
    with cli.make_context("cityshade", list(args), resilient_parsing=True) as ctx:
        name, command, rest = cli.resolve_command(ctx, list(args))
    assert command is not None, f"no command {name!r}"
    sub = click.Context(command, info_name=name, parent=ctx)
    parser = command.make_parser(sub)
    try:
        parser.parse_args(args=list(rest))
    except click.UsageError as e:           # unknown option, missing value
        pytest.fail(f"{line}: {e.format_message()}")
