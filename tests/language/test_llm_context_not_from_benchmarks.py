"""The LLM's system prompt teaches the words by examples of its own: no prompt of the blind test rounds
(benchmarks/blind) may stand in it word for word, or the LLM's figures on those rounds would measure
recall of the examples, not reading. Short generic requests ("take a picture") are not looked at."""

from __future__ import annotations

import json
from pathlib import Path

from langnav.language.llm import context

BLIND = Path(__file__).resolve().parents[2] / "benchmarks" / "blind"
#: A request shorter than this is a generic one any guide would give ("go to the door").
MIN_CHARS = 25


def _blind_prompts() -> set[str]:
    prompts: set[str] = set()
    for path in BLIND.glob("*/*.jsonl"):
        for line in path.read_text(encoding="utf-8").splitlines():
            if line.strip():
                prompt = str(json.loads(line).get("prompt", "")).strip().lower().rstrip(".!?")
                if len(prompt) >= MIN_CHARS:
                    prompts.add(prompt)
    return prompts


def test_no_blind_prompt_is_an_example_of_the_system_prompt() -> None:
    text = " ".join(Path(context.__file__).read_text(encoding="utf-8").lower().replace("\\\n", "").split())
    prompts = _blind_prompts()
    assert len(prompts) > 1000  # the rounds are there
    assert sorted(p for p in prompts if p in text) == []
