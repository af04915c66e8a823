"""The clause being read: its normalised text, which characters are read, and what the reading doubts."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Final

from langnav.language.intent import Step

WORD_RE: Final = re.compile(r"[a-z][a-z'-]*|\d+(?:\.\d+)?")


class Scratch:
    """The normalised clause and which of its characters have been read."""

    def __init__(self, text: str) -> None:
        self.text = text
        self._used = [False] * len(text)

    def masked(self) -> str:
        return "".join(" " if u else c for c, u in zip(self.text, self._used, strict=True))

    def use(self, start: int, end: int) -> None:
        for i in range(max(start, 0), min(end, len(self.text))):
            self._used[i] = True

    def is_free(self, start: int, end: int) -> bool:
        return not any(self._used[start:end])

    def take_all(self, pattern: re.Pattern[str]) -> list[re.Match[str]]:
        matches = list(pattern.finditer(self.masked()))
        for m in matches:
            self.use(m.start(), m.end())
        return matches

    def find(self, pattern: re.Pattern[str]) -> re.Match[str] | None:
        return pattern.search(self.masked())

    def leftover_words(self) -> list[str]:
        return WORD_RE.findall(self.masked())


@dataclass
class Clause:
    text: str                  # as the user wrote it
    s: Scratch
    previous: Step | None
    factors: list[float] = field(default_factory=list)
    lost: list[str] = field(default_factory=list)
    elliptical: bool = False   # no verb: the movement is borrowed from the previous step
    amends: bool = False       # only a number: it completes the previous step
    had_verb: bool = False     # a movement verb was read
    out_of_range: bool = False  # a number beyond what a step may hold
    explore_verb: bool = False  # "explore the unknown area on your left" (a trip towards it)
    through_previous: bool = False  # "stop after you pass through it": the previous step goes through
    asks: list[str] = field(default_factory=list)  # what the reading would have to guess: ask instead
    guessed_direction: bool = False  # a move said with no way: forward is assumed ("go 2 m")

    def doubt(self, factor: float) -> None:
        self.factors.append(factor)
