"""The evaluation metrics: normalisation, alignment, clarify cases, validity; reports; and agreement
with the bench's referee on the dev cases."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from langnav.eval.cases import MapCache, load_cases
from langnav.eval.metrics import ValidityMap, align, normalise, score_case, summarise
from langnav.eval.report import write_report
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid


@pytest.fixture(scope="module")
def room() -> ValidityMap:
    b = MapBuilder(6.0, 5.0)
    b.room(0.5, 0.5, 5.5, 4.5)
    b.box(2.5, 2.0, 3.0, 2.5)
    return ValidityMap(b.build("metrics_room"))


def ntp(*poses: list[float]) -> dict[str, Any]:
    return {"command": "NavigateThroughPoses", "poses": list(poses)}


def test_normalise_joins_and_sums() -> None:
    cmds = [ntp([1, 1]), ntp([2, 2]), {"command": "Stop"}, {"command": "Move", "direction": "forward", "repeat": 10},
            {"command": "Move", "direction": "forward", "repeat": 5}, {"command": "Rotate", "direction": "left",
                                                                        "repeat": 9}]
    assert normalise(cmds) == [ntp([1, 1], [2, 2]), {"command": "Move", "direction": "forward", "repeat": 15},
                               {"command": "Rotate", "direction": "left", "repeat": 9}]
    assert normalise([{"command": "Stop"}, {"command": "Stop"}]) == [{"command": "Stop"}]
    assert normalise("junk") == []


def test_pose_checks(room: ValidityMap) -> None:
    comp = room.component_of(1.0, 1.0)
    assert room.reachable(1.5, 1.5, comp)
    assert not room.valid(2.75, 2.25)        # on the box
    assert not room.valid(0.6, 2.0)          # 0.1 m from the wall
    assert room.valid(0.675, 2.0)            # 0.175 m from the wall (cell centres)


def test_case_scoring_and_why(room: ValidityMap) -> None:
    case = {"id": "c1", "prompt": "p", "pose": [1.0, 1.0, 0.0],
            "expect": [{"command": "Rotate", "direction": "any", "repeat": [17, 19]},
                       {"command": "NavigateThroughPoses", "goal": {"circle": [4.0, 3.5, 0.75]},
                        "via": [{"polygon": [[3.5, 0.5], [5.5, 0.5], [5.5, 2.0], [3.5, 2.0]]}]}]}
    right = score_case(case, {"commands": [{"command": "Rotate", "direction": "right", "repeat": 18},
                                           ntp([4.5, 1.5], [4.0, 3.4])]}, room)
    assert right.right and right.matched == 2 and right.why == []
    no_via = score_case(case, {"commands": [{"command": "Rotate", "direction": "left", "repeat": 18},
                                            ntp([4.0, 3.4])]}, room)
    assert not no_via.right and no_via.matched == 1
    assert no_via.why == ["expected NavigateThroughPoses 2: via region 1 (polygon x 3.5..5.5, y 0.5..2.0) not "
                          "visited on the way", "extra NavigateThroughPoses (produced command 2)"]
    bad_pose = score_case(case, {"commands": [ntp([2.75, 2.25], [4.0, 3.4])]}, room)
    assert bad_pose.ntp_flags == [False, True]
    assert "expected Rotate 1: nothing of that type produced" in bad_pose.why
    missing = score_case(case, None, room)
    assert missing.why == ["no output line for this case"] and missing.produced == 0


def test_clarify_cases(room: ValidityMap) -> None:
    case = {"id": "k", "prompt": "go to the kitchen", "pose": [1.0, 1.0, 0.0], "expect": "clarify"}
    assert score_case(case, {"commands": [], "clarification": "where is it?"}, room).right
    assert not score_case(case, {"commands": [], "clarification": None}, room).right
    wrong = score_case(case, {"commands": [ntp([2, 2])], "clarification": None}, room)
    assert not wrong.right and wrong.produced == 1 and wrong.expected == 0


def test_alignment_is_in_order(room: ValidityMap) -> None:
    comp = room.component_of(1.0, 1.0)
    exp = [{"command": "Rotate", "direction": "left", "repeat": [8, 10]},
           {"command": "Move", "direction": "forward", "repeat": [30, 36]}]
    got = [{"command": "Move", "direction": "forward", "repeat": 33}, {"command": "Rotate", "direction": "left",
                                                                       "repeat": 9}]
    assert len(align(exp, got, room, comp)) == 1


def test_summary_and_move_validity(room: ValidityMap) -> None:
    cases = [{"id": "a", "prompt": "a", "pose": [1.0, 1.0, 0.0],
              "expect": [{"command": "Move", "direction": "forward", "repeat": [30, 36]}]},
             {"id": "b", "prompt": "b", "pose": [1.0, 1.0, 180.0],
              "expect": [{"command": "Move", "direction": "forward", "repeat": [10, 20]}]}]
    outs = [{"commands": [{"command": "Move", "direction": "forward", "repeat": 33}]},
            {"commands": [{"command": "Move", "direction": "forward", "repeat": 15}]}]  # into the west wall
    results = [score_case(c, o, room) for c, o in zip(cases, outs, strict=True)]
    s = summarise(results)
    assert (s.right, s.cases) == (2, 2)
    assert (s.move_valid, s.move_all) == (1, 2)
    assert s.by_type["Move"].f1 == 1.0 and s.overall.precision == 1.0


def test_reports(room: ValidityMap, tmp_path: Path) -> None:
    case = {"id": "c", "prompt": "turn left", "pose": [1.0, 1.0, 0.0],
            "expect": [{"command": "Rotate", "direction": "left", "repeat": [8, 10]}]}
    results = [score_case(case, {"commands": [{"command": "Rotate", "direction": "right", "repeat": 9}]}, room)]
    s = summarise(results)
    md, png = write_report(tmp_path / "r.md", s, results, "t", 0.5)
    text = md.read_text()
    assert "## Misses (1 of 1)" in text and "direction right is not left" in text and png.stat().st_size > 1000
    (html,) = write_report(tmp_path / "r.html", s, results, "t", 0.5)
    assert "<svg" in html.read_text() and "turn left" in html.read_text()


def _synthetic_output(case: Any, grid: OccupancyGrid) -> dict[str, Any]:
    """Commands built from the expectations (some right, some wrong), to compare two scorers."""
    exp = case.expect
    if exp == "clarify":
        return {"id": case.id, "commands": [], "clarification": "?"}
    if isinstance(exp, dict):
        exp = exp["any"][0]
    cmds: list[dict[str, Any]] = []
    for i, e in enumerate(exp):
        if e["command"] in ("Move", "Rotate"):
            d = "left" if e["direction"] == "any" else e["direction"]
            cmds.append({"command": e["command"], "direction": d, "repeat": e["repeat"][i % 2] + (i % 3) - 1})
        elif e["command"] == "NavigateThroughPoses":
            g = e["goal"]
            pt = g["circle"][:2] if "circle" in g else [sum(p[0] for p in g["polygon"]) / len(g["polygon"]),
                                                        sum(p[1] for p in g["polygon"]) / len(g["polygon"])]
            cmds.append(ntp(pt))
        else:
            cmds.append({"command": e["command"]})
    return {"id": case.id, "commands": cmds, "clarification": None}


def test_agrees_with_the_bench_referee(shared_dir: Path, tmp_path: Path) -> None:
    cases_path = shared_dir / "bench" / "prompts_dev.jsonl"
    cases = load_cases(cases_path)
    maps = MapCache(cases_path.parent)
    outs = [_synthetic_output(c, maps.get(c)) for c in cases]
    out_path = tmp_path / "out.jsonl"
    out_path.write_text("\n".join(json.dumps(o) for o in outs) + "\n")
    vms: dict[int, ValidityMap] = {}
    results = []
    for c, o in zip(cases, outs, strict=True):
        g = maps.get(c)
        results.append(score_case(c.model_dump(), o, vms.setdefault(id(g), ValidityMap(g))))
    ours = summarise(results).to_json()
    theirs = json.loads(subprocess.run([sys.executable, str(shared_dir / "bench" / "score.py"), str(cases_path),
                                        str(out_path), "--json"], capture_output=True, text=True, check=True,
                                       timeout=120).stdout)
    for key in ("prompt_accuracy", "command_precision", "command_recall", "command_f1", "ntp_pose_validity",
                "move_validity"):
        assert ours[key] == theirs[key], key
    assert 0 < ours["prompt_accuracy"] < 1  # the synthetic outputs are partly wrong: both scorers see it
