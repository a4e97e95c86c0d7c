"""A bash completion script made from the argument parser (no extra dependency)."""

from __future__ import annotations

import argparse


def _options(p: argparse.ArgumentParser) -> list[str]:
    return sorted(o for a in p._actions for o in a.option_strings)


def _subparsers(p: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for a in p._actions:
        if isinstance(a, argparse._SubParsersAction):
            return dict(a.choices)
    return {}


def bash_script(parser: argparse.ArgumentParser, templates: list[str]) -> str:
    """Return a bash script completing commands, options, choices, templates and scene files."""
    subs = _subparsers(parser)
    cases = []
    for name, sp in subs.items():
        choices = []
        for a in sp._actions:
            if a.option_strings and a.choices:
                opts = "|".join(a.option_strings)
                words = " ".join(str(c) for c in a.choices)
                choices.append(f'        {opts}) COMPREPLY=($(compgen -W "{words}" -- "$cur")); '
                               "return;;")
        positional = ""
        if name == "new":
            positional = " ".join(templates)
        elif name == "completion":
            positional = "bash"
        files = "" if name in ("new", "completion", "doctor") else \
            '\n      COMPREPLY+=($(compgen -f -X "!*.@(toml|dxf|csv)" -- "$cur") ' \
            '$(compgen -d -- "$cur"))'
        cases.append(
            f"    {name})\n      case \"$prev\" in\n" + "\n".join(choices)
            + ("\n" if choices else "") + "      esac\n"
            f'      COMPREPLY=($(compgen -W "{" ".join(_options(sp))} {positional}" -- "$cur"))'
            f"{files};;")
    commands = " ".join(subs)
    top = " ".join(_options(parser))
    return f"""# bash completion for mechplan: eval "$(mechplan completion bash)"
_mechplan() {{
  local cur prev cmd
  cur="${{COMP_WORDS[COMP_CWORD]}}"
  prev="${{COMP_WORDS[COMP_CWORD-1]}}"
  cmd="${{COMP_WORDS[1]}}"
  shopt -s extglob
  if [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "{commands} {top}" -- "$cur"))
    return
  fi
  case "$cmd" in
{chr(10).join(cases)}
  esac
}}
complete -o filenames -F _mechplan mechplan
"""
