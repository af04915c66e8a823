"""Places the user named ("call this spot the kitchen"), kept across restarts.

>>> store = JsonPlaceStore(Path("~/.langnav/places.json"))            # doctest: +SKIP
>>> store.put(NamedPlace.spot("Kitchen", 3.2, 4.0, yaw_deg=90.0))     # doctest: +SKIP
>>> store.get("the kitchen").xy                                        # doctest: +SKIP
(3.2, 4.0)

``PlaceStore`` is the seam: the planner, the CLI and the web app take any implementation
(``MemoryPlaceStore`` for tests and one-off runs, ``JsonPlaceStore`` for a file kept across restarts).
"""

from langnav.places.errors import BadPlaceName, PlaceError, UnknownPlace
from langnav.places.store import (
    DEFAULT_PLACES_PATH,
    PLACES_ENV,
    JsonPlaceStore,
    MemoryPlaceStore,
    NamedPlace,
    PlaceStore,
    place_key,
    places_path,
)

__all__ = ["DEFAULT_PLACES_PATH", "PLACES_ENV", "BadPlaceName", "JsonPlaceStore", "MemoryPlaceStore", "NamedPlace",
           "PlaceError", "PlaceStore", "UnknownPlace", "place_key", "places_path"]
