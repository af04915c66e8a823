"""The Planner: translation, grounding and validation end to end, refusals as clarifications,
the analysis cache, re-grounding; and the translate / eval CLIs on a tiny case file."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import AnalysisParams
from langnav.cli import main
from langnav.language.errors import TranslationError
from langnav.language.intent import Intent, Step
from langnav.language.translator import Context, register
from langnav.maps.grid import OccupancyGrid
from langnav.maps.io import save_map
from langnav.pipeline import Planner

AT_A = (3.0, 2.0, 0.0)


class Fixed:
    """A test translator: a fixed reading per prompt."""

    name = "fixed"

    def __init__(self, readings: dict[str, Intent]) -> None:
        self.readings = readings

    def translate(self, prompt: str, context: Context) -> Intent:
        if prompt not in self.readings:
            raise TranslationError(f"cannot read {prompt!r}")
        return self.readings[prompt]


READINGS = {
    "through the door then left door": Intent(translator="fixed", steps=[
        Step.model_validate({"movement": "navigate", "detail": "through", "target": {"kind": "door"}}),
        Step.model_validate({"movement": "navigate", "target": {"kind": "door", "side": "left"}})]),
    "third door": Intent(translator="fixed", steps=[
        Step.model_validate({"movement": "navigate", "target": {"kind": "door", "ordinal": 3}})]),
    "far": Intent(translator="fixed", steps=[
        Step.model_validate({"movement": "move", "direction": "forward", "distance_m": 20})]),
    "sandwich": Intent(translator="fixed", clarification="I cannot make sandwiches."),
}


@pytest.fixture(scope="module")
def world(two_rooms: MapAnalysis) -> MapAnalysis:
    return two_rooms


def test_plan_and_items(world: MapAnalysis) -> None:
    planner = Planner(Fixed(READINGS))
    r = planner.plan("through the door then left door", world, AT_A)
    assert r.ok and r.translator == "fixed" and len(r.items) == 2
    assert [len(it.commands) for it in r.items] == [1, 1]
    assert r.commands[0].poses[-1] == [6.875, 1.975]
    # re-ground the second step from a pose of the moment: back in room A facing east
    again = r.items[1].reground((3.0, 2.0, 0.0), world)
    assert again[0].poses[-1] == [5.675, 4.975]
    assert r.to_bench("x") == {"id": "x", "commands": [
        {"command": "NavigateThroughPoses", "poses": [[5.575, 1.975], [6.875, 1.975]]},
        {"command": "NavigateThroughPoses", "poses": [[6.475, 4.975]]}], "clarification": None}


@pytest.mark.parametrize(("prompt", "reason"), [
    ("third door", "only two doors"),
    ("far", "into a wall"),
    ("sandwich", "I cannot make sandwiches."),
    ("gibberish", "cannot read 'gibberish'"),
    ("", "the prompt is empty"),
])
def test_refusals_become_clarifications(world: MapAnalysis, prompt: str, reason: str) -> None:
    r = Planner(Fixed(READINGS)).plan(prompt, world, AT_A)
    assert not r.ok and r.commands == () and reason in (r.clarification or "")
    assert r.to_bench("c")["commands"] == []


def test_bad_pose_is_a_clarification(world: MapAnalysis) -> None:
    r = Planner(Fixed(READINGS)).plan("third door", world, (float("nan"), 0.0, 0.0))
    assert r.clarification is not None and "finite" in r.clarification


def test_analysis_is_computed_once_per_grid(world: MapAnalysis) -> None:
    calls: list[OccupancyGrid] = []

    def analyzer(grid: OccupancyGrid, params: AnalysisParams) -> MapAnalysis:
        calls.append(grid)
        return world

    planner = Planner(Fixed(READINGS), analyzer=analyzer)
    for _ in range(3):
        planner.plan("third door", world.grid, AT_A)
        planner.plan("through the door then left door", world.grid, AT_A)
    assert calls == [world.grid]


def test_named_places(world: MapAnalysis) -> None:
    planner = Planner(Fixed({"kitchen": Intent(steps=[Step.model_validate(
        {"movement": "navigate", "target": {"kind": "room", "name": "kitchen"}})])}))
    assert "don't know a place called 'kitchen'" in (planner.plan("kitchen", world, AT_A).clarification or "")
    planner.name_place("Kitchen", (9.0, 3.0))
    r = planner.plan("kitchen", world, AT_A)
    assert r.ok and r.commands[0].note == "to 'Kitchen'"


def _case_file(tmp_path: Path, world: MapAnalysis) -> Path:
    save_map(world.grid, tmp_path / "maps" / "two_rooms.yaml")
    lines = [{"id": "a", "map": "maps/two_rooms.yaml", "pose": list(AT_A), "prompt": "third door",
              "expect": "clarify"},
             {"id": "b", "map": "maps/two_rooms.yaml", "pose": list(AT_A), "prompt": "through the door then left door",
              "expect": [{"command": "NavigateThroughPoses", "goal": {"circle": [6.075, 5.0, 0.75]},
                          "via": [{"polygon": [[6.2, 1.0], [8.0, 1.0], [8.0, 3.0], [6.2, 3.0]]}]}]},
             {"id": "c", "map": "maps/two_rooms.yaml", "pose": list(AT_A), "prompt": "far",
              "expect": [{"command": "Move", "direction": "forward", "repeat": [600, 700]}]}]
    path = tmp_path / "cases.jsonl"
    path.write_text("\n".join(json.dumps(x) for x in lines) + "\n")
    return path


@pytest.fixture()
def fixed_registered(world: MapAnalysis) -> str:
    register("fixed-test", lambda: Fixed(READINGS))
    return "fixed-test"


def test_translate_cases_cli(tmp_path: Path, world: MapAnalysis, fixed_registered: str,
                             capsys: pytest.CaptureFixture[str]) -> None:
    cases = _case_file(tmp_path, world)
    assert main(["translate", "--cases", str(cases), "--translator", fixed_registered]) == 0
    out = [json.loads(x) for x in capsys.readouterr().out.splitlines()]
    assert [o["id"] for o in out] == ["a", "b", "c"]
    assert out[0]["commands"] == [] and "only two doors" in out[0]["clarification"]
    # the CLI analyses the saved map itself: the goal is door_2's room-B side, within 0.75 m of it
    last = out[1]["commands"][-1]["poses"][-1]
    assert out[1]["clarification"] is None and last[0] > 6.15 and abs(last[1] - 5.0) < 0.75


def test_translate_one_prompt_cli(tmp_path: Path, world: MapAnalysis, fixed_registered: str,
                                  capsys: pytest.CaptureFixture[str]) -> None:
    cases = _case_file(tmp_path, world)
    yaml = cases.parent / "maps" / "two_rooms.yaml"
    rc = main(["translate", "--map", str(yaml), "--pose", "3,2,0", "--translator", fixed_registered, "--json",
               "through the door then left door"])
    doc = json.loads(capsys.readouterr().out)
    assert rc == 0 and doc["translator"] == "fixed" and len(doc["steps"]) == 2
    assert doc["commands"][1]["note"] == "to the door on your left"
    assert main(["translate", "--map", str(yaml), "--pose", "3,2", "--translator", fixed_registered, "x"]) == 2


def test_eval_cli(tmp_path: Path, world: MapAnalysis, fixed_registered: str,
                  capsys: pytest.CaptureFixture[str]) -> None:
    cases = _case_file(tmp_path, world)
    rc = main(["eval", "--cases", str(cases), "--translator", fixed_registered, "--report", str(tmp_path / "r.md"),
               "--json"])
    summary = json.loads(capsys.readouterr().out)
    assert rc == 0
    assert summary["prompt_accuracy"] == pytest.approx(2 / 3, abs=1e-4)  # "far" is refused: the case wanted a Move
    assert summary["command_recall"] == 0.5 and summary["command_precision"] == 1.0
    report = (tmp_path / "r.md").read_text()
    assert "### c: far" in report and (tmp_path / "r.png").exists()


class Broken:
    name = "broken"

    def translate(self, prompt: str, context: Context) -> Intent:
        raise ZeroDivisionError("a bug")


def test_a_bug_is_refused_not_raised(world: MapAnalysis, caplog: pytest.LogCaptureFixture) -> None:
    r = Planner(Broken()).plan("anything", world, AT_A)
    assert r.commands == () and "internal error (ZeroDivisionError: a bug)" in (r.clarification or "")
    assert "planning 'anything' failed" in caplog.text


def test_a_prompt_that_runs_nothing_always_says_why(world: MapAnalysis) -> None:
    # "go to the room" standing in room A: nothing to drive, and the reply says so (never silence)
    here = {"here": Intent(translator="fixed", steps=[
        Step.model_validate({"movement": "navigate", "target": {"kind": "room", "in_current_room": True}})],
        unread=["sofa"])}
    r = Planner(Fixed(here)).plan("here", world, AT_A)
    assert r.commands == ()
    said = r.to_bench("x")["clarification"]
    assert said is not None and "already" in said and "'sofa'" in said
    assert said == " ".join(r.messages)
