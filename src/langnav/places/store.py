"""The named-place store: a ``PlaceStore`` Protocol, an in-memory store and a JSON file store.

A place is a point of the map frame (metres, the frame of the map it was named on), an optional
heading, and what was named: the robot's spot (``kind`` ``"spot"``) or an element of the map ("name
this room the lab": ``kind`` ``"room"`` and the element's id when it was named). Names are matched
by :func:`place_key`: case, surrounding articles and spacing do not count ("The Kitchen" = "kitchen").

The file store keeps one JSON document (validated by pydantic when read and written), replaced
atomically on every change (a temporary file in the same folder, flushed, then renamed), and read
again when another process changed it (the CLI's ``langnav places`` while the web app runs).
"""

from __future__ import annotations

import json
import logging
import math
import os
import re
import tempfile
import threading
import time
from collections.abc import Iterable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Annotated, Final, Literal, Protocol, runtime_checkable

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from langnav.places.errors import BadPlaceName, PlaceError, UnknownPlace

log = logging.getLogger(__name__)

#: Where ``langnav run`` and ``langnav serve`` keep named places unless told otherwise.
DEFAULT_PLACES_PATH: Final = Path("~/.langnav/places.json")
#: The environment variable that moves the places file (one file per building or map, say).
PLACES_ENV: Final = "LANGNAV_PLACES"
#: A name is a short phrase a person says ("the charging dock"), not a sentence.
MAX_NAME_CHARS: Final = 80
#: A store holds at most this many places: a floor's worth of names, and a bound on the file a
#: careless script could grow.
MAX_PLACES: Final = 500
FILE_VERSION: Final = 1
#: What a place names: the robot's spot, or an element of the map of that kind.
PlaceKind = Literal["spot", "room", "hallway", "door", "corner", "wall", "obstacle", "narrow_passage",
                    "unexplored_area"]
PLACE_KINDS: Final[tuple[str, ...]] = ("spot", "room", "hallway", "door", "corner", "wall", "obstacle",
                                       "narrow_passage", "unexplored_area")

_ARTICLES_RE: Final = re.compile(r"^(?:(?:the|a|an|my|our|your)(?:\s+|$))+")
_EDGE_JUNK_RE: Final = re.compile(r"^[\s\"'`“”‘’.,;:!?()\[\]]+|[\s\"'`“”‘’.,;:!?()\[\]]+$")
_CONTROL_RE: Final = re.compile(r"[\x00-\x1f\x7f]")
#: Labels drawn on the map ("door 2", "room 3"): names a prompt already uses for that element.
_LABEL_RE: Final = re.compile(r"^(?:door|room|hallway|corridor|hall|wall|corner|obstacle|passage|"
                              r"narrow\s+passage|unexplored(?:\s+area)?)\s*#?\s*\d+$")
#: Kinds of element: a place named so would hide every element of that kind ("go to the door").
ELEMENT_WORDS: Final = frozenset({"door", "doorway", "room", "hallway", "corridor", "hall", "wall", "corner", "obstacle",
                                  "passage", "narrow passage", "unexplored area", "opening", "entrance", "exit"})
#: Words that already mean a place in a prompt: naming a place so would hide that meaning.
RESERVED_NAMES: Final = frozenset({"here", "there", "this", "that", "it", "me", "you", "start", "the start",
                                   "where you started", "where you were"})


def places_path(given: str | os.PathLike[str] | None = None) -> Path:
    """The places file: ``given`` if any, else $LANGNAV_PLACES, else ~/.langnav/places.json (expanded)."""
    if given is not None:
        return Path(given).expanduser()
    env = os.environ.get(PLACES_ENV, "").strip()
    return Path(env).expanduser() if env else DEFAULT_PLACES_PATH.expanduser()


def place_key(name: str) -> str:
    """The form names are matched by: lower case, single spaces, no leading article, no quotes."""
    s = _EDGE_JUNK_RE.sub("", " ".join(str(name).lower().split()))
    s = _ARTICLES_RE.sub("", s)
    return _EDGE_JUNK_RE.sub("", s)


def clean_name(name: str) -> str:
    """The name as it is shown: the user's words without a leading article, quotes or extra spaces.
    Raises BadPlaceName when it cannot be a name, saying why."""
    if not isinstance(name, str):
        raise BadPlaceName(f"a place name must be text, not {type(name).__name__}")
    if _CONTROL_RE.search(name):
        raise BadPlaceName("a place name cannot hold control characters (tabs, new lines)")
    shown = _EDGE_JUNK_RE.sub("", " ".join(name.split()))
    shown = re.sub(r"^(?:(?:the|a|an|my|our|your)(?:\s+|$))+", "", shown, flags=re.IGNORECASE)
    shown = _EDGE_JUNK_RE.sub("", shown)
    key = place_key(shown)
    if not key:
        raise BadPlaceName("a place needs a name, e.g. 'call this spot the kitchen'")
    if len(shown) > MAX_NAME_CHARS:
        raise BadPlaceName(f"a place name has at most {MAX_NAME_CHARS} characters; '{shown[:40]}...' is longer")
    if _LABEL_RE.match(key):
        raise BadPlaceName(f"'{shown}' is a label the map already shows for one of its elements; "
                           "choose another name, e.g. 'the kitchen'")
    if key in ELEMENT_WORDS:
        raise BadPlaceName(f"'{shown}' is what the map calls a kind of element; choose a name of its own, "
                           f"e.g. 'the kitchen {key}'")
    if key in RESERVED_NAMES:
        raise BadPlaceName(f"'{shown}' already means something in an instruction; choose another name, "
                           "e.g. 'the charging dock'")
    return shown


@dataclass(frozen=True)
class NamedPlace:
    """A place the user named, in the map frame."""

    name: str
    x_m: float
    y_m: float
    yaw_deg: float | None = None
    kind: str = "spot"
    element_id: str | None = None
    created_s: float = 0.0

    def __post_init__(self) -> None:
        if not all(math.isfinite(v) for v in (self.x_m, self.y_m)):
            raise PlaceError(f"place '{self.name}' needs a finite position, not ({self.x_m}, {self.y_m})")
        if self.yaw_deg is not None and not math.isfinite(self.yaw_deg):
            raise PlaceError(f"place '{self.name}' has a heading that is not a number ({self.yaw_deg})")
        if self.kind not in PLACE_KINDS:
            raise PlaceError(f"place '{self.name}' has kind {self.kind!r}; it must be one of {', '.join(PLACE_KINDS)}")

    @classmethod
    def spot(cls, name: str, x_m: float, y_m: float, yaw_deg: float | None = None) -> NamedPlace:
        """The robot's spot (or any point) under a name; the name is checked and cleaned."""
        return cls(clean_name(name), float(x_m), float(y_m), None if yaw_deg is None else float(yaw_deg) % 360.0,
                   "spot", None, time.time())

    @classmethod
    def element(cls, name: str, kind: str, element_id: str | None, x_m: float, y_m: float) -> NamedPlace:
        """An element of the map under a name; (x_m, y_m) is a point of it (a room's: inside it)."""
        return cls(clean_name(name), float(x_m), float(y_m), None, kind, element_id, time.time())

    @property
    def key(self) -> str:
        return place_key(self.name)

    @property
    def xy(self) -> tuple[float, float]:
        return (self.x_m, self.y_m)

    def to_json(self) -> dict[str, object]:
        return _Record.from_place(self).model_dump(mode="json")


@runtime_checkable
class PlaceStore(Protocol):
    """Named places by name. ``put`` replaces a place of the same name; names match by ``place_key``."""

    def get(self, name: str) -> NamedPlace | None: ...

    def all(self) -> list[NamedPlace]: ...

    def put(self, place: NamedPlace) -> NamedPlace: ...

    def remove(self, name: str) -> NamedPlace: ...

    def rename(self, old: str, new: str) -> NamedPlace: ...


# ------------------------------------------------------------------------------ file boundary
class _Record(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    name: Annotated[str, Field(min_length=1, max_length=MAX_NAME_CHARS)]
    x_m: float
    y_m: float
    yaw_deg: float | None = None
    kind: PlaceKind = "spot"
    element_id: Annotated[str, Field(max_length=80)] | None = None
    created_s: Annotated[float, Field(ge=0)] = 0.0

    @field_validator("x_m", "y_m", "yaw_deg")
    @classmethod
    def _finite(cls, v: float | None) -> float | None:
        if v is not None and not math.isfinite(v):
            raise ValueError("must be a finite number")
        return v

    @classmethod
    def from_place(cls, p: NamedPlace) -> _Record:
        return cls(name=p.name, x_m=round(p.x_m, 4), y_m=round(p.y_m, 4),
                   yaw_deg=None if p.yaw_deg is None else round(p.yaw_deg, 2), kind=p.kind,  # type: ignore[arg-type]
                   element_id=p.element_id, created_s=round(p.created_s, 3))

    def to_place(self) -> NamedPlace:
        return NamedPlace(self.name, self.x_m, self.y_m, self.yaw_deg, self.kind, self.element_id, self.created_s)


class _PlacesFile(BaseModel):
    model_config = ConfigDict(extra="forbid")

    version: Literal[1] = FILE_VERSION
    places: list[_Record] = Field(default_factory=list, max_length=MAX_PLACES)


# ------------------------------------------------------------------------------ stores
class MemoryPlaceStore:
    """Named places kept in memory (tests, one-off CLI runs). Thread-safe."""

    def __init__(self, places: Iterable[NamedPlace] = ()) -> None:
        self._lock = threading.RLock()
        self._places: dict[str, NamedPlace] = {}
        for p in places:
            self._places[p.key] = p

    def get(self, name: str) -> NamedPlace | None:
        with self._lock:
            self._refresh()
            return self._places.get(place_key(name))

    def all(self) -> list[NamedPlace]:
        with self._lock:
            self._refresh()
            return sorted(self._places.values(), key=lambda p: p.key)

    def put(self, place: NamedPlace) -> NamedPlace:
        with self._lock:
            self._refresh()
            if place.key not in self._places and len(self._places) >= MAX_PLACES:
                raise PlaceError(f"I already know {MAX_PLACES} places, the most I keep; forget one first "
                                 "(e.g. 'forget the kitchen')")
            before = dict(self._places)
            self._places[place.key] = place
            self._commit(before)
            return place

    def remove(self, name: str) -> NamedPlace:
        with self._lock:
            self._refresh()
            key = place_key(name)
            if key not in self._places:
                raise UnknownPlace(self._unknown_message(name))
            before = dict(self._places)
            gone = self._places.pop(key)
            self._commit(before)
            return gone

    def rename(self, old: str, new: str) -> NamedPlace:
        with self._lock:
            self._refresh()
            key = place_key(old)
            if key not in self._places:
                raise UnknownPlace(self._unknown_message(old))
            shown = clean_name(new)
            if place_key(shown) != key and place_key(shown) in self._places:
                raise PlaceError(f"I already know a place called '{self._places[place_key(shown)].name}'; "
                                 "forget it first or choose another name")
            before = dict(self._places)
            place = replace(self._places.pop(key), name=shown)
            self._places[place.key] = place
            self._commit(before)
            return place

    def _unknown_message(self, name: str) -> str:
        known = ", ".join(f"'{p.name}'" for p in sorted(self._places.values(), key=lambda p: p.key))
        return (f"I don't know a place called '{clean_name_or_raw(name)}'. "
                + (f"The places I know: {known}." if known else "I know no named places yet; name one first: "
                   "'call this spot the kitchen'."))

    # hooks for the file store
    def _refresh(self) -> None:
        return None

    def _commit(self, before: dict[str, NamedPlace]) -> None:
        return None


def clean_name_or_raw(name: str) -> str:
    try:
        return clean_name(name)
    except BadPlaceName:
        return " ".join(str(name).split())[:MAX_NAME_CHARS]


class JsonPlaceStore(MemoryPlaceStore):
    """Named places in a JSON file, written atomically on each change and re-read when it changes.

    A missing file is an empty store (created on the first change); a file that is not a valid
    places file raises PlaceError naming the file (it is never overwritten behind the user's back).
    """

    def __init__(self, path: str | os.PathLike[str]) -> None:
        super().__init__()
        self.path = Path(path).expanduser()
        self._stamp: tuple[int, int] | None = None
        with self._lock:
            self._refresh()

    def _file_stamp(self) -> tuple[int, int] | None:
        try:
            st = self.path.stat()
        except FileNotFoundError:
            return None
        except OSError as exc:
            raise PlaceError(f"cannot read the places file {self.path}: {exc}") from exc
        return (st.st_mtime_ns, st.st_size)

    def _refresh(self) -> None:
        stamp = self._file_stamp()
        if stamp == self._stamp:
            return
        if stamp is None:
            self._places = {}
            self._stamp = None
            return
        try:
            raw = self.path.read_text(encoding="utf-8")
            doc = _PlacesFile.model_validate(json.loads(raw))
        except (OSError, UnicodeDecodeError, json.JSONDecodeError, ValidationError) as exc:
            raise PlaceError(f"the places file {self.path} cannot be read ({type(exc).__name__}: "
                             f"{str(exc).splitlines()[0][:200]}); fix or move it away, then try again") from exc
        places: dict[str, NamedPlace] = {}
        for rec in doc.places:
            try:
                p = rec.to_place()
            except PlaceError as exc:
                raise PlaceError(f"the places file {self.path} holds a bad place: {exc}") from exc
            places[p.key] = p
        self._places = places
        self._stamp = stamp

    def _commit(self, before: dict[str, NamedPlace]) -> None:
        doc = _PlacesFile(places=[_Record.from_place(p) for p in sorted(self._places.values(), key=lambda p: p.key)])
        text = json.dumps(doc.model_dump(mode="json"), indent=1, ensure_ascii=False) + "\n"
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(prefix=".places-", suffix=".tmp", dir=self.path.parent)
            try:
                with os.fdopen(fd, "w", encoding="utf-8") as f:
                    f.write(text)
                    f.flush()
                    os.fsync(f.fileno())
                os.replace(tmp, self.path)
            except BaseException:
                Path(tmp).unlink(missing_ok=True)
                raise
        except OSError as exc:
            self._places = before
            raise PlaceError(f"cannot write the places file {self.path}: {exc}") from exc
        self._stamp = self._file_stamp()
        log.info("places file %s now holds %d places", self.path, len(self._places))
