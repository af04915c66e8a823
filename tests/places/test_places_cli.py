"""``langnav places`` and the places file of ``langnav run`` / ``langnav translate``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from langnav.cli import main
from langnav.maps.draw import MapBuilder
from langnav.maps.io import save_map
from langnav.places import JsonPlaceStore


def test_add_list_rename_forget(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    f = str(tmp_path / "places.json")
    assert main(["places", "--file", f]) == 0
    assert "no named places" in capsys.readouterr().out
    assert main(["places", "add", "the", "kitchen", "3.2,4.0,90", "--file", f]) == 0
    assert main(["places", "add", "dock", "1,2", "--file", f]) == 0
    assert main(["places", "rename", "dock", "charging dock", "--file", f]) == 0
    capsys.readouterr()
    assert main(["places", "list", "--json", "--file", f]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert [(p["name"], p["x_m"], p["y_m"], p["yaw_deg"]) for p in listed] == [
        ("charging dock", 1.0, 2.0, None), ("kitchen", 3.2, 4.0, 90.0)]
    assert main(["places", "forget", "kitchen", "--file", f]) == 0
    assert main(["places", "forget", "kitchen", "--file", f]) == 2
    assert "I don't know a place called 'kitchen'" in capsys.readouterr().err
    assert main(["places", "add", "door", "2", "1,1", "--file", f]) == 2
    assert main(["places", "add", "kitchen", "--file", f]) == 2
    assert [p.name for p in JsonPlaceStore(Path(f)).all()] == ["charging dock"]


def test_the_environment_moves_the_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("LANGNAV_PLACES", str(tmp_path / "here.json"))
    assert main(["places", "add", "lab", "1,1"]) == 0
    assert (tmp_path / "here.json").is_file()


def test_translate_reads_named_places_and_never_writes_them(tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    b = MapBuilder(6.0, 4.0)
    b.room(0.5, 0.5, 5.5, 3.5)
    save_map(b.build("box"), tmp_path / "box.yaml")
    f = tmp_path / "places.json"
    assert main(["places", "add", "kitchen", "4.5,2.0", "--file", str(f)]) == 0
    capsys.readouterr()
    args = ["translate", "--map", str(tmp_path / "box.yaml"), "--pose", "1.5,2,0", "--places", str(f), "--json"]
    assert main([*args, "go to the kitchen"]) == 0
    out = json.loads(capsys.readouterr().out)
    (pose,) = out["commands"][0]["poses"]
    assert abs(pose[0] - 4.5) <= 0.75 and abs(pose[1] - 2.0) <= 0.75
    assert main([*args, "forget the kitchen"]) == 0
    assert [p.name for p in JsonPlaceStore(f).all()] == ["kitchen"]  # a dry run: the file is unchanged
