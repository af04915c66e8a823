"""The ``langnav`` command. Each subcommand lives in its own module of this package, with
``add_arguments(parser)`` and ``run(args) -> int``; this is the only place library errors
become exit codes (2 = bad input / refused, 1 = failure)."""

from __future__ import annotations

import argparse
import importlib
import logging
import sys
from collections.abc import Sequence
from typing import Final

from langnav.errors import LangnavError

#: subcommand -> (module, one-line help)
SUBCOMMANDS: Final[dict[str, tuple[str, str]]] = {
    "analyze": ("langnav.cli.analyze", "find rooms, doors, walls, corners, obstacles, passages and unexplored areas"),
    "translate": ("langnav.cli.translate", "prompt -> intent -> validated robot commands"),
    "eval": ("langnav.cli.evaluate", "the paper's metrics over a case file"),
    "run": ("langnav.cli.run", "translate, validate and execute a prompt on a robot"),
    "sim": ("langnav.cli.sim", "run the simulated robot (optionally served over rosbridge)"),
    "serve": ("langnav.cli.serve", "the web app: chat + live map"),
    "node": ("langnav.cli.node", "langnav as a ROS 2 node: /langnav/instruct, /langnav/stop, map markers"),
    "places": ("langnav.cli.places", "list, add, forget or rename the places you named"),
}


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="langnav", description="Drive a ROS 2 robot in plain language.")
    parser.add_argument("-v", "--verbose", action="store_true", help="log debug messages")
    sub = parser.add_subparsers(dest="command", required=True)
    for name, (module, help_text) in SUBCOMMANDS.items():
        try:
            mod = importlib.import_module(module)
        except ModuleNotFoundError as exc:
            if exc.name == module:
                continue  # not built yet in this checkout
            raise
        p = sub.add_parser(name, help=help_text, description=help_text)
        mod.add_arguments(p)
        p.set_defaults(_run=mod.run)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.DEBUG if args.verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")
    try:
        return int(args._run(args))
    except (LangnavError, argparse.ArgumentTypeError) as exc:
        print(f"langnav {args.command}: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:  # a file or socket the OS refused: say which and why, without a traceback
        where = f"{exc.filename}: " if getattr(exc, "filename", None) else ""
        print(f"langnav {args.command}: {where}{exc.strerror or exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
