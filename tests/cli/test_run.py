"""``langnav run`` end to end on a built world: JSON lines, the last one's exact shape, exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from langnav.cli import main
from langnav.maps.draw import MapBuilder
from langnav.maps.io import save_map


@pytest.fixture
def world_yaml(tmp_path: Path) -> Path:
    b = MapBuilder(8.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 4.0)
    b.box(4.2, 2.8, 4.8, 3.4)
    yaml_path, _ = save_map(b.build("cli room"), tmp_path / "room.yaml")
    return yaml_path


def lines(out: str) -> list[dict[str, object]]:
    return [json.loads(line) for line in out.splitlines() if line.strip()]


def test_json_run_moves_and_ends_with_the_finished_line(world_yaml: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--world", str(world_yaml), "--pose", "1,2,0", "--known-map", "--json",
                 "move forward 1 meter, then turn left"])
    events = lines(capsys.readouterr().out)
    assert code == 0
    last = events[-1]
    assert set(last) == {"event", "status", "pose"}
    assert last["event"] == "finished" and last["status"] == "succeeded"
    x, y, yaw = last["pose"]  # type: ignore[misc]
    assert x == pytest.approx(1.99, abs=0.03) and y == pytest.approx(2.0, abs=0.03)
    assert yaw == pytest.approx(90.0, abs=2.0)
    kinds = [e["event"] for e in events if e["event"] != "progress"]
    assert kinds == ["plan", "started", "succeeded", "started", "succeeded", "finished"]


def test_a_refused_prompt_runs_nothing(world_yaml: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--world", str(world_yaml), "--pose", "1,2,0", "--known-map", "--json", "go to the kitchen"])
    events = lines(capsys.readouterr().out)
    assert code == 2
    assert events[0]["event"] == "rejected" and events[0]["message"]
    assert events[-1] == {"event": "finished", "status": "rejected", "pose": [1.0, 2.0, 0.0]}


def test_text_output_names_each_step(world_yaml: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--world", str(world_yaml), "--pose", "1,2,0", "--known-map", "turn right 30 degrees"])
    out = capsys.readouterr().out
    assert code == 0
    assert "Turn right 30°" in out
    assert out.strip().splitlines()[-1].startswith("finished: succeeded at (1.00, 2.00, -30°)")
