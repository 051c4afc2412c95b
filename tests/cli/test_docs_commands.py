"""Every ``cityshade`` command line written in the README, the user guide, the demo script and
the examples of ``--help`` parses: its
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


def _help_examples():
    from cityshade.cli.helpfmt import EXAMPLES

    for name, lines in EXAMPLES.items():
        for line in lines:
            yield pytest.param(line, id=f"help {name}:{line[:50]}")


def test_the_docs_have_commands():
    assert len(list(_cases())) >= 10


@pytest.mark.parametrize("line", [*_cases(), *_help_examples()])
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


def test_help_groups_every_option_under_a_heading():
    from click.testing import CliRunner

    from cityshade.cli.helpfmt import EXAMPLES, SECTIONS
    from cityshade.cli.main import COMMANDS

    for name in COMMANDS:
        out = CliRunner().invoke(cli, [name, "--help"]).output
        assert "Other options:" not in out, f"{name}: an option under no heading"
        headings = [h for h in [*SECTIONS, "Help", "Examples"] if f"\n{h}:\n" in out]
        positions = [out.index(f"\n{h}:\n") for h in headings]
        assert positions == sorted(positions) and len(headings) >= 3, (name, headings)
        assert "Help" in headings and "Examples" in headings, name
        assert all(line in out for line in EXAMPLES[name]), name


def test_the_readme_stays_short_and_every_picture_and_link_it_names_exists():
    """Issue 40's goal (≤ 150 lines), and no picture or local link pointing at nothing."""
    text = (REPO / "README.md").read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 150
    targets = re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", text)
    assert any(t.endswith(".png") for t in targets)
    for target in targets:
        if not re.match(r"[a-z]+:", target):
            assert (REPO / target).is_file(), target
