"""The bundled demo world: a small floor drawn with :class:`~langnav.maps.draw.MapBuilder`.

Three rooms off a hallway, doors between them, furniture, a narrow passage between two
shelves, an unscanned corner and an exit to the unexplored outside. The files in
``langnav/data`` are generated from :func:`build_demo_grid`; regenerate them with
``python -m langnav.maps.demo`` after changing it (a test checks that they agree).
"""

from __future__ import annotations

import sys
from importlib import resources
from pathlib import Path
from typing import Final

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid
from langnav.maps.io import save_map

#: The word the CLI accepts in place of a map file.
DEMO_NAME: Final = "demo"
DEMO_FILE: Final = "demo.yaml"
#: Where the demo robot starts (x_m, y_m, yaw_deg): in the hallway's west end, facing east along
#: it, so the first screen shows doors ahead on both sides, rooms through them and the unscanned
#: corner beyond: every starter example in the web app has something to act on from here.
DEMO_START: Final = (1.5, 4.95, 0.0)
#: The demo robot starts with the floor already mapped (as a robot with a saved slam_toolbox map
#: does): rooms, doors and furniture have names from the first second; the unscanned corner and
#: the exit are still there to explore.
DEMO_KNOWN_MAP: Final = True


def build_demo_grid() -> OccupancyGrid:
    """The demo floor: 16 m x 11 m at 5 cm, origin (-1, -1)."""
    b = MapBuilder(16.0, 11.0, resolution_m=0.05, origin=(-1.0, -1.0))
    # Hallway along y in [4.15, 5.75]; rooms south and north of it.
    b.room(0.0, 4.15, 14.0, 5.75)
    b.room(0.0, 0.0, 6.0, 4.0)  # south-west room
    b.room(6.15, 0.0, 14.0, 4.0)  # south-east room (with the shelves)
    b.room(0.0, 5.9, 8.0, 9.0)  # north room
    # Doors into the hallway, one between the two south rooms, an exit east to the outside.
    b.door_h(3.0, 4.075, 0.9).door_h(11.5, 4.075, 0.9).door_h(4.0, 5.825, 1.0)
    b.door_v(6.075, 1.0, 0.9)
    b.door_v(14.075, 4.95, 1.2)
    # Furniture: a table in the north room, a sofa and a pillar, two shelves with a passage between.
    b.box(2.0, 7.1, 3.6, 7.9)
    b.box(1.0, 0.3, 3.2, 1.0)
    b.disc(8.0, 5.3, 0.15)
    b.box(8.5, 1.1, 10.5, 1.4).box(8.5, 2.05, 10.5, 2.35)
    # The north room's east end was never scanned.
    b.unknown(6.0, 7.3, 8.0, 9.0)
    return b.build(source="demo")


def demo_map_path() -> Path:
    """The bundled demo map's YAML (the CLI's ``demo``)."""
    return Path(str(resources.files("langnav") / "data" / DEMO_FILE))


def write_demo(directory: Path) -> Path:
    """Write the demo map (YAML + PGM) into ``directory``; returns the YAML path."""
    yaml_path, _ = save_map(build_demo_grid(), directory / DEMO_FILE)
    return yaml_path


def main() -> int:
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else demo_map_path().parent
    print(write_demo(target))
    return 0


if __name__ == "__main__":
    sys.exit(main())
