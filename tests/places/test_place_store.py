"""The named-place store: names, the in-memory and JSON file stores (kept across restarts, atomic,
re-read when another process writes, never overwriting a file it cannot read)."""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from langnav.places import (
    BadPlaceName,
    JsonPlaceStore,
    MemoryPlaceStore,
    NamedPlace,
    PlaceError,
    PlaceStore,
    UnknownPlace,
    place_key,
)
from langnav.places.store import MAX_NAME_CHARS, clean_name


@pytest.mark.parametrize(("name", "key"), [
    ("The Kitchen", "kitchen"), ("  my   charging dock ", "charging dock"), ('"the lab."', "lab"),
    ("Bob's office", "bob's office"), ("the the hall closet", "hall closet")])
def test_names_match_without_case_articles_or_spacing(name: str, key: str) -> None:
    assert place_key(name) == key


@pytest.mark.parametrize(("name", "why"), [
    ("", "needs a name"), ("the", "needs a name"), ("door 2", "label the map already shows"),
    ("Room 3", "label the map already shows"), ("here", "already means"), ("door", "kind of element"),
    ("x" * (MAX_NAME_CHARS + 1), "at most"), ("kit\nchen", "control characters")])
def test_bad_names_are_refused_with_the_reason(name: str, why: str) -> None:
    with pytest.raises(BadPlaceName, match=why):
        clean_name(name)


def test_shown_names_keep_the_users_words() -> None:
    assert clean_name("the Charging Dock") == "Charging Dock"
    assert NamedPlace.spot("the kitchen", 1.0, 2.0, yaw_deg=-90.0).yaw_deg == 270.0


def test_positions_must_be_finite() -> None:
    with pytest.raises(PlaceError, match="finite"):
        NamedPlace.spot("kitchen", math.nan, 0.0)


@pytest.mark.parametrize("make", [lambda p: MemoryPlaceStore(), lambda p: JsonPlaceStore(p / "places.json")])
def test_put_get_rename_remove(tmp_path: Path, make) -> None:  # type: ignore[no-untyped-def]
    store: PlaceStore = make(tmp_path)
    assert isinstance(store, PlaceStore)
    store.put(NamedPlace.spot("Kitchen", 1.0, 2.0, 90.0))
    store.put(NamedPlace.element("the lab", "room", "room_3", 5.0, 6.0))
    assert store.get("the kitchen") == store.get("KITCHEN")
    got = store.get("kitchen")
    assert got is not None and got.xy == (1.0, 2.0) and got.yaw_deg == 90.0
    store.put(NamedPlace.spot("kitchen", 3.0, 4.0))  # the same name: replaced
    assert [p.name for p in store.all()] == ["kitchen", "lab"]
    assert store.get("kitchen").xy == (3.0, 4.0)  # type: ignore[union-attr]
    renamed = store.rename("lab", "the workshop")
    assert renamed.name == "workshop" and renamed.element_id == "room_3" and store.get("lab") is None
    with pytest.raises(PlaceError, match="already know a place called 'kitchen'"):
        store.rename("workshop", "Kitchen")
    assert store.remove("workshop").name == "workshop"
    with pytest.raises(UnknownPlace, match=r"I don't know a place called 'workshop'.*'kitchen'"):
        store.remove("workshop")


def test_the_file_keeps_places_across_restarts_and_is_written_atomically(tmp_path: Path) -> None:
    path = tmp_path / "sub" / "places.json"
    JsonPlaceStore(path).put(NamedPlace.spot("dock", 1.5, -2.25, 180.0))
    assert [f.name for f in path.parent.iterdir()] == ["places.json"]  # no temporary file left behind
    doc = json.loads(path.read_text())
    assert doc["version"] == 1 and doc["places"][0]["name"] == "dock" and doc["places"][0]["kind"] == "spot"
    again = JsonPlaceStore(path).get("dock")
    assert again is not None and again.xy == (1.5, -2.25) and again.yaw_deg == 180.0


def test_another_process_writing_the_file_is_seen(tmp_path: Path) -> None:
    path = tmp_path / "places.json"
    server = JsonPlaceStore(path)
    cli = JsonPlaceStore(path)
    cli.put(NamedPlace.spot("kitchen", 1.0, 1.0))
    st_ = path.stat()
    os.utime(path, ns=(st_.st_atime_ns, st_.st_mtime_ns + 1_000_000))  # coarse file systems: a new stamp
    assert server.get("kitchen") is not None


def test_a_file_that_is_not_a_places_file_is_never_overwritten(tmp_path: Path) -> None:
    path = tmp_path / "places.json"
    path.write_text('{"version": 1, "places": [{"name": "x", "x_m": "NaN", "y_m": 0}]}')
    with pytest.raises(PlaceError, match="cannot be read"):
        JsonPlaceStore(path)
    path.write_text("not json")
    with pytest.raises(PlaceError, match="fix or move it away"):
        JsonPlaceStore(path)
    assert path.read_text() == "not json"


def test_a_failed_write_leaves_the_store_as_it_was(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "places.json"
    store = JsonPlaceStore(path)
    store.put(NamedPlace.spot("dock", 0.0, 0.0))

    def disk_full(src: str, dst: str) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", disk_full)
    with pytest.raises(PlaceError, match=r"cannot write .*No space left"):
        store.put(NamedPlace.spot("kitchen", 1.0, 1.0))
    assert [p.name for p in store.all()] == ["dock"]
    assert [f.name for f in tmp_path.iterdir()] == ["places.json"]  # the temporary file was removed


@settings(max_examples=60, deadline=None, derandomize=True)
@given(name=st.text(alphabet=st.characters(categories=["L", "N", "Zs"]), min_size=1, max_size=40),
       x=st.floats(-1e4, 1e4), y=st.floats(-1e4, 1e4), yaw=st.none() | st.floats(-720, 720))
def test_a_place_read_back_from_the_file_is_the_place_written(tmp_path_factory: pytest.TempPathFactory, name: str,
                                                             x: float, y: float, yaw: float | None) -> None:
    try:
        place = NamedPlace.spot(name, x, y, yaw)
    except BadPlaceName:
        return
    path = tmp_path_factory.mktemp("p") / "places.json"
    JsonPlaceStore(path).put(place)
    back = JsonPlaceStore(path).get(name)
    assert back is not None and back.name == place.name and back.kind == "spot"
    assert back.xy == pytest.approx(place.xy, abs=1e-4)
    assert (back.yaw_deg is None) == (place.yaw_deg is None)
