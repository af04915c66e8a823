"""The intent: what a prompt asks for, as data (the paper's prompt template).

One :class:`Step` per instruction, in order. A step names a *reference element* and its
*properties*, a *movement type* and a *movement detail*; never coordinates. This schema is
also the JSON schema given to LLM translators; their answers are parsed into it and validated.
"""

from __future__ import annotations

from enum import StrEnum
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator


class Element(StrEnum):
    DOOR = "door"
    WALL = "wall"
    ROOM = "room"
    HALLWAY = "hallway"
    NARROW_PASSAGE = "narrow_passage"
    OBSTACLE = "obstacle"
    CORNER = "corner"
    UNEXPLORED_AREA = "unexplored_area"
    NONE = "none"


class Movement(StrEnum):
    NAVIGATE = "navigate"   # go somewhere relative to an element
    MOVE = "move"           # straight line: forward / backward / left / right
    ROTATE = "rotate"       # turn in place
    STOP = "stop"
    FOLLOW = "follow"       # follow / drive along a wall or hallway
    QUERY = "query"         # where are you, what path, show the map
    EXPLORE = "explore"     # frontier exploration until done ("explore", "map this floor")
    NAME_PLACE = "name_place"      # "call this spot the kitchen": remember a place (no motion)
    FORGET_PLACE = "forget_place"  # "forget the kitchen": drop a remembered place (no motion)


class Detail(StrEnum):
    TO = "to"
    NEXT_TO = "next_to"
    TOWARDS = "towards"
    THROUGH = "through"
    OPPOSITE_SIDE_OF = "opposite_side_of"
    ALONG = "along"
    BETWEEN = "between"
    STOP_AT = "stop_at"
    MIDDLE = "middle"


class Side(StrEnum):
    """Where the element lies relative to the robot (or, for corners and walls of a room,
    which one: "the left corner", "the right wall")."""

    LEFT = "left"
    RIGHT = "right"
    AHEAD = "ahead"
    BEHIND = "behind"


class Superlative(StrEnum):
    NEAREST = "nearest"
    FARTHEST = "farthest"
    BIGGEST = "biggest"
    SMALLEST = "smallest"
    WIDEST = "widest"
    NARROWEST = "narrowest"


class Direction(StrEnum):
    FORWARD = "forward"
    BACKWARD = "backward"
    LEFT = "left"
    RIGHT = "right"
    AROUND = "around"  # rotate 180 degrees, either way


class Query(StrEnum):
    POSE = "pose"
    PATH = "path"
    MAP = "map"
    PLACES = "places"  # "what places do you know?": the places the user has named


class Amount(StrEnum):
    """A move or turn given without a number."""

    LITTLE = "little"   # "a bit", "slightly": 0.3 m or 20 degrees
    DEFAULT = "default"  # "turn left" alone: 90 degrees


class Place(StrEnum):
    """A place that is no element of the map (``ElementRef.kind`` is ``none``)."""

    START = "start"  # where the robot stood when this prompt began ("go back", "return to where you started")
    PREVIOUS = "previous"  # where the robot was before its last move ("go back to where you were")


class Offset(StrEnum):
    """Which way ``Step.offset_m`` is measured from the target, along the robot's way."""

    PAST = "past"      # "2 m past the door", "a metre beyond the box"
    BEFORE = "before"  # "stop 1 m before the corner", "half a metre short of the wall"


class Relation(StrEnum):
    """How a room or hallway lies relative to another space (``ElementRef.near``, else the robot's)."""

    ADJACENT = "adjacent"  # "the room next to this one": joined by a door or only a wall apart
    ACROSS = "across"      # "the room across the hall": on the far side of the hallway
    #: "the room two doors down (the hall)": counting the doors of the hallway from the robot's own space
    #: (its room's door, or the robot in the hallway) the way it faces, the room behind the Nth door
    #: (``ordinal`` = N; ``side`` the hallway side when said, "behind" for "two doors back")
    DOORS_ALONG = "doors_along"


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, use_enum_values=False)


class Landmark(_Model):
    """Another element that tells which one is meant ("the door next to THE BOX", "the corner of THE
    BIGGEST ROOM"): the same properties as :class:`ElementRef`, one level deep."""

    kind: Element
    ordinal: Annotated[int, Field(ge=1, le=20)] | None = None
    superlative: Superlative | None = None
    side: Side | None = None
    in_current_room: bool = False
    within: Element | None = None
    label: Annotated[int, Field(ge=0, le=9999)] | None = None  # "the room next to room 3"


class ElementRef(_Model):
    """A reference to one element of the map, by kind and the properties the words give."""

    kind: Element
    ordinal: Annotated[int, Field(ge=1, le=20)] | None = Field(
        default=None, description="first = 1, second = 2 ... counted by distance from the robot")
    superlative: Superlative | None = None
    side: Side | None = Field(default=None, description="relative to the robot: left, right, ahead, behind")
    also_side: Side | None = Field(
        default=None, description="a second side that narrows the first to a quarter: 'the door behind you on "
        "the left' -> side behind, also_side left; 'the room ahead on your right' -> side ahead, also_side right")
    in_current_room: bool = Field(default=False, description="'this room', 'the room you are in'")
    within: Element | None = Field(
        default=None, description="the space that contains it: 'the corner of the hallway' -> hallway")
    name: Annotated[str, Field(max_length=80)] | None = Field(
        default=None, description="a proper name the map cannot know ('kitchen', 'the desk')")
    near: Landmark | None = Field(
        default=None, description="the element it lies in or next to, when the words name one with its own "
        "properties: 'the door next to the box' -> {kind: obstacle}; 'the corner of the biggest room' -> "
        "{kind: room, superlative: biggest}; 'the room at the end of the hallway' -> {kind: hallway}. Without "
        "an ordinal or superlative of its own, the element nearest to it is meant")
    place: Place | None = Field(
        default=None, description="with kind 'none': a place that is no map element; 'start' = where the "
        "robot was when this prompt began ('go back', 'come back', 'return to where you started'); 'previous' "
        "= where it was before its last move ('go back to where you were')")
    # -- composition (issue 9 items 3-5) ---------------------------------------------------------
    label: Annotated[int, Field(ge=0, le=9999)] | None = Field(
        default=None, description="the number of the label drawn on the map: 'door 2' -> kind door, label 2 "
        "(the element door_2); not an order by distance")
    relation: Relation | None = Field(
        default=None, description="rooms and hallways: 'adjacent' ('the room next to this one') or 'across' "
        "('the room across the hall') relative to the space in 'near' (default: the robot's); 'doors_along' "
        "('the room two doors down': ordinal 2, counted along the hallway the way the robot faces)")
    passed: bool = Field(
        default=False, description="'the door you just passed': the last such element the robot's way went "
        "by or through")


class Step(_Model):
    movement: Movement
    detail: Detail | None = None
    target: ElementRef | None = None
    second_target: ElementRef | None = Field(default=None, description="the B of 'between A and B'")
    direction: Direction | None = None
    distance_m: Annotated[float, Field(ge=0, le=100)] | None = None
    angle_deg: Annotated[float, Field(ge=0, le=3600)] | None = None
    heading_deg: Annotated[float, Field(ge=0, lt=360)] | None = Field(
        default=None, description="with movement 'rotate': turn to face this compass heading of the map, "
        "degrees counter-clockwise from east (east 0, north 90, west 180, south 270), the shorter way; "
        "'go north 3 m' is this turn, then a move forward")
    amount: Amount | None = None
    query: Query | None = None
    # -- composition (issue 9 items 3-5) ---------------------------------------------------------
    offset_m: Annotated[float, Field(ge=0, le=100)] | None = Field(
        default=None, description="with 'offset': how far past / before the target to stop, along the "
        "robot's way ('2 m past the door' -> offset past, offset_m 2)")
    offset: Offset | None = None
    fraction: Annotated[float, Field(gt=0, le=1)] | None = Field(
        default=None, description="part of the way to the target or along it: 'halfway down the corridor' "
        "-> 0.5")
    place_name: Annotated[str, Field(min_length=1, max_length=80)] | None = Field(
        default=None, description="name_place / forget_place: the user's name for the place ('kitchen'); "
        "name_place with a target names that element, without one the robot's spot")
    text: Annotated[str, Field(max_length=500)] = Field(default="", description="the words of this step")

    @model_validator(mode="after")
    def _composition_fits(self) -> Step:
        if (self.offset is None) != (self.offset_m is None):
            raise ValueError("offset and offset_m come together: 'offset': 'past', 'offset_m': 2")
        if self.offset is not None and self.fraction is not None:
            raise ValueError("a step has an offset from its target or a fraction of the way, not both")
        if self.movement in (Movement.NAME_PLACE, Movement.FORGET_PLACE) and not self.place_name:
            raise ValueError(f"a {self.movement.value} step needs place_name")
        return self


class Intent(_Model):
    """The reading of a whole prompt. ``clarification`` is set (and ``steps`` may be empty) when
    the right answer is to run nothing and explain or ask: out of scope, unknown names, unsafe."""

    steps: list[Step] = Field(default_factory=list, max_length=20)
    clarification: Annotated[str, Field(max_length=500)] | None = None
    translator: str = "unknown"
    confidence: Annotated[float, Field(ge=0, le=1)] = 1.0
    unread: list[str] = Field(default_factory=list, description="parts of the prompt not understood")


Mode = Literal["offline", "gemini", "openai", "local", "auto"]
