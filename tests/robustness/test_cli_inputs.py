"""The CLI on bad maps, poses and output paths: a one-line error naming the problem and a
non-zero exit, never a traceback."""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pytest

from langnav.cli import main
from langnav.cli.options import pose_arg
from langnav.cli.serve import settings_from_args


def _world(tmp_path: Path, name: str = "room", cells: np.ndarray | None = None,
           origin: str = "[0.0, 0.0, 0.0]") -> Path:
    img = cells if cells is not None else np.zeros((60, 80), np.uint8)
    if cells is None:
        img[5:55, 5:75] = 254
    (tmp_path / f"{name}.pgm").write_bytes(f"P5\n{img.shape[1]} {img.shape[0]}\n255\n".encode() + img.tobytes())
    y = tmp_path / f"{name}.yaml"
    y.write_text(f"image: {name}.pgm\nresolution: 0.05\norigin: {origin}\n", encoding="utf-8")
    return y


def _run(argv: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str, str]:
    try:
        code = main(argv)
    except SystemExit as exc:  # argparse refusing an option
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    assert "Traceback" not in err
    return code, out, err


@pytest.mark.parametrize("text", ["1,2", "1, 2, 90", "-1.5,2,0"])
def test_pose_arg_accepts(text: str) -> None:
    x, y, yaw = pose_arg(text)
    assert (x, y, yaw) == {"1,2": (1.0, 2.0, 0.0), "1, 2, 90": (1.0, 2.0, 90.0),
                           "-1.5,2,0": (-1.5, 2.0, 0.0)}[text]


@pytest.mark.parametrize("text", ["nan,0,0", "1,1,inf", "1,1,1e309", "1", "1,2,3,4", "a,b,c", ""])
def test_pose_arg_refuses(text: str) -> None:
    with pytest.raises(argparse.ArgumentTypeError, match="--pose is X,Y"):
        pose_arg(text)


def test_analyze_unwritable_outputs(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    world = _world(tmp_path)
    (tmp_path / "adir").mkdir()
    (tmp_path / "afile").write_text("x")
    for option, target in (("--json", tmp_path / "adir"), ("--png", tmp_path / "afile" / "x.png"),
                           ("--labels", tmp_path / "afile" / "l.npy")):
        code, _, err = _run(["analyze", str(world), option, str(target)], capsys)
        assert code != 0
        assert err.startswith(f"langnav analyze: {option} ")


def test_analyze_map_errors_are_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    nan = _world(tmp_path, "nan", origin="[.nan, 0, 0]")
    code, _, err = _run(["analyze", str(nan)], capsys)
    assert code == 2
    assert err.strip().count("\n") == 0 and "nan.yaml: origin must be" in err
    code, _, err = _run(["analyze", str(_world(tmp_path, "walls", np.zeros((20, 20), np.uint8)))], capsys)
    assert code == 2 and "walls.yaml: the map has no free space" in err


@pytest.mark.parametrize("pose", ["999,999,0", "0.1,0.1,0"])
def test_translate_pose_off_the_map_or_in_a_wall(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                 pose: str) -> None:
    world = _world(tmp_path)
    code, out, _ = _run(["translate", "--map", str(world), f"--pose={pose}", "move forward 0.5 m"], capsys)
    assert code == 2
    assert "nothing will run" in out
    assert ("outside the map" in out) if pose.startswith("999") else ("occupied" in out or "wall" in out)
    assert "Check that my pose" in out  # tells the user what to do


def test_translate_nan_pose_is_refused_by_the_parser(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = _run(["translate", "--map", str(_world(tmp_path)), "--pose=nan,0,0", "stop"], capsys)
    assert code == 2 and "--pose is X,Y" in err


def test_translate_two_number_pose_means_yaw_zero(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = _run(["translate", "--map", str(_world(tmp_path)), "--pose=2,1.5", "--json",
                         "move forward 0.5 m"], capsys)
    assert code == 0
    assert '"command": "Move"' in out


def _serve_args(tmp_path: Path, **kw: object) -> argparse.Namespace:
    base: dict[str, object] = {"world": None, "backend": "sim", "translator": "offline", "host": "127.0.0.1",
                               "port": 8765, "known_map": True, "pose": None, "db": tmp_path / "chat.db"}
    base.update(kw)
    return argparse.Namespace(**base)


@pytest.mark.parametrize(("world_kind", "expect"), [
    ("missing", "missing.yaml: no such file"),
    ("walls", "no free cell to start the robot on"),
    ("dir", "is a directory"),
])
def test_serve_refuses_a_bad_world_before_starting(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                   monkeypatch: pytest.MonkeyPatch, world_kind: str,
                                                   expect: str) -> None:
    import uvicorn

    started: list[object] = []
    monkeypatch.setattr(uvicorn, "run", lambda *a, **k: started.append(a))
    world = {"missing": tmp_path / "missing.yaml", "dir": tmp_path,
             "walls": _world(tmp_path, "walls", np.zeros((20, 20), np.uint8))}[world_kind]
    code, out, err = _run(["serve", "--world", str(world), "--db", str(tmp_path / "c.db"), "--port", "8765"],
                          capsys)
    assert code == 2
    assert expect in err
    assert started == [] and "open http" not in out


def test_serve_refuses_an_unwritable_database(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                              monkeypatch: pytest.MonkeyPatch) -> None:
    import uvicorn

    monkeypatch.setattr(uvicorn, "run", lambda *a, **k: None)
    (tmp_path / "file").write_text("x")
    code, _, err = _run(["serve", "--db", str(tmp_path / "file" / "chat.db")], capsys)
    assert code == 2
    assert "cannot open the conversation database" in err and "--db" in err


def test_serve_starts_with_a_good_world(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    import uvicorn

    apps: list[object] = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **k: apps.append(app))
    code, out, _ = _run(["serve", "--world", str(_world(tmp_path)), "--pose=2,1.5,0", "--known-map",
                         "--db", str(tmp_path / "c.db")], capsys)
    assert code == 0 and len(apps) == 1
    assert "open http://127.0.0.1:8000/" in out
    assert settings_from_args(_serve_args(tmp_path)).host == "127.0.0.1"


def test_run_pose_in_a_wall_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = _run(["run", "--world", str(_world(tmp_path)), "--known-map", "--pose=0.1,0.1,0",
                         "move forward 0.5 m"], capsys)
    assert code == 2
    assert "start pose (0.10, 0.10)" in err


def test_translate_cases_with_a_missing_map_answers_every_case(tmp_path: Path,
                                                               capsys: pytest.CaptureFixture[str]) -> None:
    import json

    _world(tmp_path)
    cases = tmp_path / "cases.jsonl"
    cases.write_text(
        json.dumps({"id": "a", "map": "room.yaml", "pose": [2, 1.5, 0], "prompt": "move forward 0.5 m",
                    "expect": "clarify"}) + "\n"
        + json.dumps({"id": "b", "map": "nope.yaml", "pose": [2, 1.5, 0], "prompt": "stop", "expect": "clarify"})
        + "\n", encoding="utf-8")
    code, out, _ = _run(["translate", "--cases", str(cases)], capsys)
    assert code == 0
    a, b = (json.loads(line) for line in out.splitlines())
    assert a["commands"] == [{"command": "Move", "direction": "forward", "repeat": 17}]
    assert b["commands"] == [] and b["clarification"].startswith("cannot load the map: ")
    assert "nope.yaml: no such file" in b["clarification"]


@pytest.mark.parametrize(("option", "value"), [("--timeout", "-1"), ("--timeout", "nan"), ("--timeout", "inf"),
                                               ("--timeout", "0"), ("--seed", "-5"), ("--seed", "x")])
def test_run_refuses_bad_numbers_before_starting(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                 option: str, value: str) -> None:
    code, _, err = _run(["run", "--world", str(_world(tmp_path)), f"{option}={value}", "stop"], capsys)
    assert code == 2
    assert f"argument {option}: expected a" in err


def test_eval_report_to_an_unwritable_place(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    import json

    _world(tmp_path)
    cases = tmp_path / "cases.jsonl"
    cases.write_text(json.dumps({"id": "a", "map": "room.yaml", "pose": [2, 1.5, 0], "prompt": "stop",
                                 "expect": [{"command": "Stop"}]}) + "\n", encoding="utf-8")
    (tmp_path / "afile").write_text("x")
    code, out, err = _run(["eval", "--cases", str(cases), "--report", str(tmp_path / "afile" / "r.md")], capsys)
    assert code == 1
    assert "prompt accuracy" in out  # the table was printed before the report failed
    assert err.startswith("langnav eval: ") and "afile" in err


@pytest.mark.parametrize("command", ["run", "translate"])
def test_run_and_translate_name_a_broken_map(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                             command: str) -> None:
    bad = _world(tmp_path, "bad", origin="[0, .nan, 0]")
    argv = (["run", "--world", str(bad), "stop"] if command == "run"
            else ["translate", "--map", str(bad), "--pose=1,1,0", "stop"])
    code, _, err = _run(argv, capsys)
    assert code == 2
    assert err.startswith(f"langnav {command}: {bad}: origin must be [x, y, yaw]")
