"""``langnav places``: the places the user named, in the file ``langnav run`` and the web app use.

    langnav places [list] [--file PATH] [--json]
    langnav places add NAME X,Y[,YAW_DEG] [--file PATH]
    langnav places forget NAME [--file PATH]
    langnav places rename OLD NEW [--file PATH]

Places are also named and forgotten in prompts ("call this spot the kitchen", "forget the
kitchen", "what places do you know?"). The file is ``--file``, else ``$LANGNAV_PLACES``, else
``~/.langnav/places.json``; positions are map-frame metres of the map they were named on.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Final

from langnav.cli.options import pose_arg
from langnav.places import DEFAULT_PLACES_PATH, PLACES_ENV, JsonPlaceStore, NamedPlace, places_path

ACTIONS: Final = ("list", "add", "forget", "rename")


def add_places_option(p: argparse.ArgumentParser) -> None:
    """``--places PATH`` for the subcommands that read prompts."""
    p.add_argument("--places", type=Path, default=None, metavar="PATH",
                   help=f"named places file (default ${PLACES_ENV} or {DEFAULT_PLACES_PATH})")


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("action", nargs="?", default="list", choices=ACTIONS, help="what to do (default: list)")
    p.add_argument("words", nargs="*", help="add: NAME X,Y[,YAW_DEG]; forget: NAME; rename: OLD NEW")
    p.add_argument("--file", type=Path, default=None,
                   help=f"the places file (default ${PLACES_ENV} or {DEFAULT_PLACES_PATH})")
    p.add_argument("--json", action="store_true", help="machine-readable output")


def _usage(action: str) -> str:
    return {"add": "langnav places add NAME X,Y[,YAW_DEG]   (e.g. add kitchen 3.2,4.0,90)",
            "forget": "langnav places forget NAME", "rename": "langnav places rename OLD NEW",
            "list": "langnav places list"}[action]


def run(args: argparse.Namespace) -> int:
    store = JsonPlaceStore(places_path(args.file))
    words: list[str] = list(args.words)
    if args.action == "list":
        if words:
            raise argparse.ArgumentTypeError(f"usage: {_usage('list')}")
        places = store.all()
        if args.json:
            print(json.dumps([p.to_json() for p in places], indent=1, ensure_ascii=False))
        elif not places:
            print(f"no named places in {store.path}; name one with e.g. "
                  "langnav run \"call this spot the kitchen\" or langnav places add kitchen 3.2,4.0")
        else:
            for p in places:
                facing = "" if p.yaw_deg is None else f", facing {p.yaw_deg:.0f}°"
                what = "" if p.kind == "spot" else f" ({p.kind}{' ' + p.element_id if p.element_id else ''})"
                print(f"{p.name}: ({p.x_m:.2f}, {p.y_m:.2f}){facing}{what}")
        return 0
    if args.action == "add":
        if len(words) < 2:
            raise argparse.ArgumentTypeError(f"usage: {_usage('add')}")
        x, y, yaw = pose_arg(words[-1])
        yaw_deg = yaw if words[-1].count(",") == 2 else None
        place = store.put(NamedPlace.spot(" ".join(words[:-1]), x, y, yaw_deg))
        print(f"named ({place.x_m:.2f}, {place.y_m:.2f}) '{place.name}'")
        return 0
    if args.action == "forget":
        if not words:
            raise argparse.ArgumentTypeError(f"usage: {_usage('forget')}")
        gone = store.remove(" ".join(words))
        print(f"forgot '{gone.name}'")
        return 0
    if len(words) != 2:
        raise argparse.ArgumentTypeError(f"usage: {_usage('rename')} (quote names of several words)")
    place = store.rename(words[0], words[1])
    print(f"renamed '{words[0]}' to '{place.name}'")
    return 0


__all__ = ["PLACES_ENV", "add_places_option", "places_path"]
