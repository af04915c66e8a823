"""Settings of the web app (pydantic): which world, robot backend and translator; where to listen.

Values come from the ``langnav serve`` options, or from ``LANGNAV_*`` environment variables
(``LANGNAV_PORT=8080``) through :meth:`WebSettings.from_env`. Bound to anything but loopback
the app requires a token for every request that moves the robot (see :mod:`langnav.web.app`).
"""

from __future__ import annotations

import ipaddress
import math
import os
import secrets
from pathlib import Path
from typing import Any, Final

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from langnav.errors import LangnavError
from langnav.language.translator import MAX_PROMPT_CHARS

DEFAULT_HOST: Final = "127.0.0.1"
DEFAULT_PORT: Final = 8000
ENV_PREFIX: Final = "LANGNAV_"
#: 24 random bytes: 32 URL-safe characters, far beyond guessing over a network.
TOKEN_BYTES: Final = 24
#: A client may send this many robot-moving requests at once, then one per RATE_REFILL_S.
DEFAULT_RATE_BURST: Final = 10
#: Seconds to earn one more request: a person types a prompt every few seconds at most.
DEFAULT_RATE_REFILL_S: Final = 1.0
#: The state stream's top rate: the sim's map and pose change little within 100 ms.
DEFAULT_STATE_HZ: Final = 10.0


class SettingsError(LangnavError):
    """The web app was configured wrongly (bad option, missing token)."""


def is_loopback(host: str) -> bool:
    """True for 127.0.0.0/8, ::1 and ``localhost``: only this machine can connect."""
    if host.strip().lower() == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def make_token() -> str:
    return secrets.token_urlsafe(TOKEN_BYTES)


class WebSettings(BaseModel):
    """Everything ``create_app`` needs. Frozen: one app, one configuration."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    world: Path | None = Field(default=None, description="map YAML or image; None = the bundled demo world")
    backend: str = Field(default="sim", description="robot backend name (sim, rosbridge, ros2)")
    translator: str = Field(default="offline", description="translator name (offline, auto, gemini, openai, local)")
    host: str = DEFAULT_HOST
    port: int = Field(default=DEFAULT_PORT, ge=0, le=65535)
    token: str | None = Field(default=None, min_length=16,
                              description="required for robot-moving requests when host is not loopback")
    known_map: bool | None = Field(
        default=None, description="the robot starts with the world map as its own; None = the world's "
                                  "default (the bundled demo floor was mapped before, any other world starts unknown)")
    start_pose: tuple[float, float, float] | None = Field(
        default=None, description="x_m, y_m, yaw_deg; None = the world's default start")
    db_path: Path = Field(default=Path("langnav.db"), description="SQLite file of the conversation")
    places_path: Path | None = Field(
        default=None, description="JSON file of the named places (kept across restarts); None = next to db_path")
    max_prompt_chars: int = Field(default=MAX_PROMPT_CHARS, ge=1, le=MAX_PROMPT_CHARS)
    rate_burst: int = Field(default=DEFAULT_RATE_BURST, ge=1)
    rate_refill_s: float = Field(default=DEFAULT_RATE_REFILL_S, gt=0)
    state_hz: float = Field(default=DEFAULT_STATE_HZ, gt=0, le=DEFAULT_STATE_HZ)
    backend_options: dict[str, Any] = Field(default_factory=dict,
                                            description="extra keyword options for the backend factory")

    @field_validator("host")
    @classmethod
    def _host_not_empty(cls, v: str) -> str:
        if not v.strip():
            raise ValueError("host must not be empty; use 127.0.0.1 to serve this machine only")
        return v.strip()

    @field_validator("start_pose")
    @classmethod
    def _pose_finite(cls, v: tuple[float, float, float] | None) -> tuple[float, float, float] | None:
        if v is not None and not all(math.isfinite(c) for c in v):
            raise ValueError(f"start_pose must be three finite numbers (x_m, y_m, yaw_deg), got {v}")
        return v

    @property
    def places_file(self) -> Path:
        """Where the named places are kept: ``places_path``, else beside the conversation database."""
        return self.places_path if self.places_path is not None else self.db_path.with_suffix(".places.json")

    @property
    def requires_token(self) -> bool:
        """Bound beyond loopback, every request that moves the robot must carry the token."""
        return not is_loopback(self.host)

    def checked(self) -> WebSettings:
        """Self, after checking that a non-loopback bind has a token."""
        if self.requires_token and not self.token:
            raise SettingsError(
                f"host {self.host} is reachable from other machines, so a token is required; "
                "`langnav serve` makes one and prints it, or set LANGNAV_TOKEN")
        return self

    @classmethod
    def from_env(cls, environ: dict[str, str] | None = None, **overrides: Any) -> WebSettings:
        """Settings from ``LANGNAV_<FIELD>`` variables, then ``overrides`` (which win)."""
        env = os.environ if environ is None else environ
        values: dict[str, Any] = {}
        for name in cls.model_fields:
            raw = env.get(ENV_PREFIX + name.upper())
            if raw is not None and name not in ("backend_options", "start_pose"):
                values[name] = raw
        values.update({k: v for k, v in overrides.items() if v is not None})
        try:
            return cls.model_validate(values)
        except ValidationError as exc:
            problems = "; ".join(f"{'.'.join(map(str, e['loc']))}: {e['msg']}" for e in exc.errors())
            raise SettingsError(f"invalid web settings: {problems}") from exc
