"""The bench's case files: one JSON object per line (id, map, pose, prompt, expect)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from langnav.errors import LangnavError
from langnav.maps.grid import OccupancyGrid
from langnav.maps.io import load_map

if TYPE_CHECKING:
    from langnav.pipeline import Planner


class CaseError(LangnavError):
    """A case file that cannot be read."""


class BenchCase(BaseModel):
    model_config = ConfigDict(extra="allow", frozen=True)

    id: str
    map: str
    pose: tuple[float, float, float]
    prompt: str
    expect: Any = Field(default=None, description="normalised commands, 'clarify', or {'any': [...]}")


def load_cases(path: str | Path) -> list[BenchCase]:
    p = Path(path)
    try:
        lines = p.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise CaseError(f"{p}: cannot read the case file: {exc}") from exc
    cases: list[BenchCase] = []
    for n, line in enumerate(lines, 1):
        if not line.strip():
            continue
        try:
            cases.append(BenchCase.model_validate(json.loads(line)))
        except json.JSONDecodeError as exc:
            raise CaseError(f"{p}:{n}: not JSON: {exc.msg}") from exc
        except ValidationError as exc:
            first = exc.errors()[0]
            raise CaseError(f"{p}:{n}: bad case: {first['msg']} at {'.'.join(map(str, first['loc']))}") from exc
    return cases


class MapCache:
    """Maps of a case file, loaded once each (paths relative to the case file's folder)."""

    def __init__(self, base: Path) -> None:
        self.base = base
        self._maps: dict[Path, OccupancyGrid] = {}

    def path(self, case: BenchCase) -> Path:
        return (self.base / case.map).resolve()

    def get(self, case: BenchCase) -> OccupancyGrid:
        mp = self.path(case)
        if mp not in self._maps:
            self._maps[mp] = load_map(mp)
        return self._maps[mp]


def bench_output(planner: Planner, maps: MapCache, case: BenchCase) -> dict[str, Any]:
    """One case's bench output line. A map that cannot be loaded is that case's refusal (with
    the reason), so one broken case does not stop a whole run."""
    try:
        grid = maps.get(case)
    except LangnavError as exc:
        return {"id": case.id, "commands": [], "clarification": f"cannot load the map: {exc}"}
    planner.history.clear()  # each case is a session of its own: no trail from the cases before it
    return planner.plan(case.prompt, grid, case.pose).to_bench(case.id)
