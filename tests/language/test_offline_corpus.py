"""The offline translator against a held-out style corpus of prompts written to the bench README.

Each line of ``data/offline_cases.jsonl``: ``prompt``; ``expect`` (a list of steps without their
``text``, or ``"clarify"``); optional ``min_confidence`` / ``max_confidence`` and ``known_names``.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from langnav.language.intent import Intent, Step
from langnav.language.offline import translate_offline

CASES_PATH = Path(__file__).parent / "data" / "offline_cases.jsonl"
#: Angles from radians are compared to this many decimals.
ANGLE_DECIMALS = 2


def _load() -> list[dict[str, Any]]:
    with CASES_PATH.open(encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


CASES = _load()


def _comparable(step: Step) -> Step:
    update: dict[str, Any] = {"text": ""}
    if step.angle_deg is not None:
        update["angle_deg"] = round(step.angle_deg, ANGLE_DECIMALS)
    if step.distance_m is not None:
        update["distance_m"] = round(step.distance_m, 4)
    return step.model_copy(update=update)


def _expected_steps(expect: list[dict[str, Any]]) -> list[Step]:
    return [_comparable(Step.model_validate(s)) for s in expect]


def test_corpus_is_big_and_varied() -> None:
    prompts = [c["prompt"].lower() for c in CASES]
    assert len(CASES) >= 150
    assert len(set(prompts)) >= len(prompts) - 2  # only the known-name case repeats a prompt
    movements = {s["movement"] for c in CASES if isinstance(c["expect"], list) for s in c["expect"]}
    assert movements == {"navigate", "move", "rotate", "stop", "follow", "query", "explore"}
    assert sum(c["expect"] == "clarify" for c in CASES) >= 15


@pytest.mark.parametrize("case", CASES, ids=[f"{i:03d}" for i in range(len(CASES))])
def test_corpus_case(case: dict[str, Any]) -> None:
    intent: Intent = translate_offline(case["prompt"], case.get("known_names", ()))
    assert intent.translator == "offline"
    if case["expect"] == "clarify":
        assert intent.steps == [], f"{case['prompt']!r} should ask, not move"
        assert intent.clarification and len(intent.clarification) > 20
    else:
        got = [_comparable(s) for s in intent.steps]
        assert got == _expected_steps(case["expect"]), case["prompt"]
        assert intent.clarification is None
        assert all(s.text for s in intent.steps)
    if "min_confidence" in case:
        assert intent.confidence >= case["min_confidence"], (case["prompt"], intent.unread)
    if "max_confidence" in case:
        assert intent.confidence <= case["max_confidence"], case["prompt"]
