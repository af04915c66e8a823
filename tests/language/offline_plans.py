"""What the offline translator makes of a prompt, as plain values a test can compare."""

from __future__ import annotations

from langnav.language.offline.translator import translate_offline

#: One step as (movement, direction, metres, degrees), amounts rounded to 0.1 mm / 0.0001 degree.
Plan = list[tuple[str, str | None, float | None, float | None]]


def plan(prompt: str) -> Plan:
    """The steps the offline translator reads in ``prompt``."""
    intent = translate_offline(prompt)
    return [(s.movement.value, s.direction.value if s.direction else None,
             None if s.distance_m is None else round(s.distance_m, 4),
             None if s.angle_deg is None else round(s.angle_deg, 4)) for s in intent.steps]


def asks(prompt: str) -> bool:
    """Whether the translator runs nothing and asks instead."""
    intent = translate_offline(prompt)
    return intent.steps == [] and bool(intent.clarification)
