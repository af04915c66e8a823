"""The FastAPI app: the page, a JSON API, and a WebSocket stream of robot state and chat events.

Routes
  GET  /                  the page (static, hand-written, no CDN)
  GET  /api/status        backend, connection, translator, plan state
  GET  /api/history       the conversation (``?after=ID&limit=N``)
  GET  /api/map.png       the robot's current map as an image
  POST /api/prompt        {"text": ...}: translate, validate, show, run       (token, rate limit)
  POST /api/goto          {"x": .., "y": ..}: a clicked point, validated, run (token, rate limit)
  POST /api/resume        resume a paused plan                                 (token, rate limit)
  POST /api/translator    {"name": ...}: choose the translator                 (token)
  POST /api/stop          stop now; never refused (stopping is always safe)
  POST /api/pause         pause the running plan (the robot halts)
  WS   /ws                state frames (<= 10 Hz), map when it changes, chat events

Safety: robot-moving requests need ``Content-Type: application/json`` (so a foreign web page
cannot send them without a CORS preflight, which this app never grants) and, when the app is
bound beyond loopback, the token. Every error is JSON for the API and an escaped HTML page for
a browser; text from users and models is never put into HTML unescaped.
"""

from __future__ import annotations

import asyncio
import contextlib
import html
import logging
import math
import secrets
import threading
import time
from collections import OrderedDict
from collections.abc import AsyncIterator, Awaitable, Callable
from importlib import resources
from pathlib import Path
from typing import Any, Final
from urllib.parse import urlsplit

from fastapi import Depends, FastAPI, HTTPException, Request, WebSocket, WebSocketDisconnect
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, HTMLResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles
from pydantic import BaseModel, ConfigDict, Field
from starlette.exceptions import HTTPException as StarletteHTTPException

from langnav.errors import LangnavError
from langnav.language.errors import TranslationError
from langnav.plan.errors import PlanRejected
from langnav.robot.errors import RobotError
from langnav.web.broadcast import Subscriber, encode
from langnav.web.session import RobotSession, SessionBusy
from langnav.web.settings import WebSettings
from langnav.web.store import MAX_HISTORY_ROWS

log = logging.getLogger(__name__)

STATIC_DIR: Final = Path(str(resources.files("langnav.web") / "static"))
#: Largest request body: a prompt of MAX_PROMPT_CHARS in UTF-8 with JSON escapes fits in 16 kB.
MAX_BODY_BYTES: Final = 16 * 1024
#: Rate-limit buckets remembered at once; the least recently seen clients are forgotten first.
MAX_RATE_CLIENTS: Final = 10_000
TOKEN_HEADER: Final = "x-langnav-token"
#: Live viewers at once: each costs a few kB/s and a little CPU; 200 is far beyond a lab's needs.
MAX_VIEWERS: Final = 200
#: Content Security Policy: only our own files; no inline script, no eval, no framing.
CSP: Final = ("default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:; "
              "connect-src 'self'; font-src 'self'; object-src 'none'; base-uri 'none'; "
              "form-action 'self'; frame-ancestors 'none'")


class SafeJSONResponse(JSONResponse):
    """JSON with ``<``, ``>``, ``&`` escaped (see :func:`langnav.web.broadcast.encode`)."""

    def render(self, content: Any) -> bytes:
        return encode(content).encode("utf-8")


# -- request bodies ------------------------------------------------------------------------------
class _Body(BaseModel):
    model_config = ConfigDict(extra="forbid")


class PromptIn(_Body):
    text: str = Field(description="what the robot should do, in plain words")
    replace: bool = Field(default=False, description="replace the running plan (after the robot asked)")


class GotoIn(_Body):
    x: float = Field(allow_inf_nan=False, description="map-frame x, metres")
    y: float = Field(allow_inf_nan=False, description="map-frame y, metres")
    yaw_deg: float | None = Field(default=None, allow_inf_nan=False, ge=-360, le=360,
                                  description="heading to stop in, degrees counter-clockwise from +x")


class PlaceIn(_Body):
    name: str = Field(min_length=1, max_length=60, description="what to call the spot")
    x: float = Field(allow_inf_nan=False, description="map-frame x, metres")
    y: float = Field(allow_inf_nan=False, description="map-frame y, metres")
    element_id: str | None = Field(default=None, max_length=60, description="name this map element instead")


class RenameIn(_Body):
    name: str = Field(min_length=1, max_length=60)
    new_name: str = Field(min_length=1, max_length=60)


class ForgetIn(_Body):
    name: str = Field(min_length=1, max_length=60)


class TranslatorIn(_Body):
    name: str = Field(max_length=40)


# -- rate limiting -------------------------------------------------------------------------------
class RateLimiter:
    """A token bucket per client: ``burst`` requests at once, then one per ``refill_s``."""

    def __init__(self, burst: int, refill_s: float, max_clients: int = MAX_RATE_CLIENTS) -> None:
        self.burst = burst
        self.refill_s = refill_s
        self._max = max_clients
        self._buckets: OrderedDict[str, tuple[float, float]] = OrderedDict()
        self._lock = threading.Lock()

    def check(self, client: str, now: float | None = None) -> float:
        """0.0 when allowed (and counted), else the seconds to wait."""
        now = time.monotonic() if now is None else now
        with self._lock:
            tokens, last = self._buckets.pop(client, (float(self.burst), now))
            tokens = min(float(self.burst), tokens + (now - last) / self.refill_s)
            wait = 0.0
            if tokens >= 1.0:
                tokens -= 1.0
            else:
                wait = (1.0 - tokens) * self.refill_s
            self._buckets[client] = (tokens, now)
            while len(self._buckets) > self._max:
                self._buckets.popitem(last=False)
        return wait


# -- errors --------------------------------------------------------------------------------------
def _wants_html(request: Request) -> bool:
    return not request.url.path.startswith("/api/") and "text/html" in request.headers.get("accept", "")


_PAGE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>{code} · langnav</title><link rel="stylesheet" href="/static/app.css"></head>
<body class="error-page"><main class="error-card"><h1>{code} · {title}</h1><p>{message}</p>
<p><a href="/">Back to langnav</a></p></main></body></html>"""


def error_response(request: Request, status: int, title: str, message: str,
                   reasons: list[str] | None = None, headers: dict[str, str] | None = None) -> Response:
    """The one shape of every error: JSON for the API, an escaped HTML page for a browser."""
    if _wants_html(request):
        body = _PAGE.format(code=status, title=html.escape(title), message=html.escape(message))
        return HTMLResponse(body, status_code=status, headers=headers)
    payload: dict[str, Any] = {"error": {"status": status, "title": title, "message": message}}
    if reasons:
        payload["error"]["reasons"] = reasons
    return SafeJSONResponse(payload, status_code=status, headers=headers)


_TITLES: Final = {400: "Bad request", 401: "Token required", 403: "Forbidden", 404: "Not found",
                  405: "Method not allowed", 409: "Busy", 413: "Too large", 415: "Unsupported type",
                  422: "Invalid request", 429: "Too many requests", 500: "Internal error",
                  503: "Robot unavailable"}


#: Library errors as HTTP answers (status, title); subclasses before their bases.
LIBRARY_ERRORS: Final[dict[type[LangnavError], tuple[int, str]]] = {
    PlanRejected: (422, "Plan rejected"),
    SessionBusy: (409, "Busy"),
    TranslationError: (400, "Not understood"),
    RobotError: (503, "Robot unavailable"),
    LangnavError: (400, "Cannot do that"),
}


def _reason(error: Any) -> str:
    """One validation error as a sentence: where in the request, and what was wrong."""
    loc = [str(p) for p in error.get("loc", ()) if p != "body"]
    if error.get("type") == "json_invalid":
        why = (error.get("ctx") or {}).get("error", "")
        at = f" at character {loc[-1]}" if loc else ""
        return f"body: not valid JSON{at}" + (f" ({why})" if why else "") + '; send e.g. {"text": "stop"}'
    return f"{'.'.join(loc) or 'body'}: {error.get('msg', '')}"


def _install_error_handlers(app: FastAPI) -> None:
    @app.exception_handler(StarletteHTTPException)
    async def _http(request: Request, exc: StarletteHTTPException) -> Response:
        title = _TITLES.get(exc.status_code, "Error")
        message = exc.detail if isinstance(exc.detail, str) else title
        if exc.status_code != 404:
            log.warning("%s %s -> %d %s: %s", request.method, request.url.path, exc.status_code, title, message)
        if exc.status_code == 404 and message == "Not Found":
            message = f"There is nothing at {request.url.path}."
        elif exc.status_code == 400 and message == "There was an error parsing the body":
            message = "The request body could not be read: send UTF-8 JSON (Content-Type: application/json)."
        return error_response(request, exc.status_code, title, message, headers=getattr(exc, "headers", None))

    @app.exception_handler(RequestValidationError)
    async def _invalid(request: Request, exc: RequestValidationError) -> Response:
        reasons = [_reason(e) for e in exc.errors()]
        log.warning("%s %s -> 422: %s", request.method, request.url.path, "; ".join(reasons))
        return error_response(request, 422, "Invalid request", "The request was not understood: "
                              + "; ".join(reasons), reasons)

    async def _library_error(request: Request, exc: Exception) -> Response:
        # the most specific class in LIBRARY_ERRORS the error is an instance of
        status, title = next(v for k, v in LIBRARY_ERRORS.items() if isinstance(exc, k))
        log.warning("%s %s -> %d %s: %s", request.method, request.url.path, status, title, exc)
        return error_response(request, status, title, str(exc), getattr(exc, "reasons", None))

    for error_class in LIBRARY_ERRORS:
        app.add_exception_handler(error_class, _library_error)

    @app.exception_handler(Exception)
    async def _crash(request: Request, exc: Exception) -> Response:
        log.exception("unhandled error on %s %s", request.method, request.url.path)
        return error_response(request, 500, "Internal error",
                              "Something went wrong inside langnav; the server log has the details.")


# -- the app -------------------------------------------------------------------------------------
def create_app(settings: WebSettings, session_factory: Callable[[WebSettings], RobotSession] | None = None
               ) -> FastAPI:
    """The web app for one robot. The session (robot, planner, executor) starts with the app's
    lifespan and closes with it; ``session_factory`` lets tests build it differently."""
    settings = settings.checked()
    factory = session_factory or RobotSession

    @contextlib.asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        session = await asyncio.to_thread(factory, settings)
        app.state.session = session
        await asyncio.to_thread(session.start)
        try:
            yield
        finally:
            await asyncio.to_thread(session.close)

    app = FastAPI(title="langnav", version="0.1.0", lifespan=lifespan, docs_url=None, redoc_url=None,
                  openapi_url="/api/openapi.json", default_response_class=SafeJSONResponse)
    app.state.settings = settings
    limiter = RateLimiter(settings.rate_burst, settings.rate_refill_s)
    app.state.limiter = limiter
    _install_error_handlers(app)

    @app.middleware("http")
    async def guard(request: Request, call_next: Callable[[Request], Awaitable[Response]]) -> Response:
        length = request.headers.get("content-length")
        if length is not None and (not length.isdigit() or int(length) > MAX_BODY_BYTES):
            return error_response(request, 413, "Too large",
                                  f"The request body is larger than {MAX_BODY_BYTES} bytes.")
        origin = request.headers.get("origin")
        if request.method == "POST" and origin and urlsplit(origin).netloc != request.headers.get("host"):
            return error_response(request, 403, "Forbidden", "Requests from other web sites are refused.")
        response = await call_next(request)
        response.headers.setdefault("Content-Security-Policy", CSP)
        response.headers.setdefault("X-Content-Type-Options", "nosniff")
        response.headers.setdefault("Referrer-Policy", "no-referrer")
        if request.url.path.startswith("/api/"):
            response.headers.setdefault("Cache-Control", "no-store")
        return response

    def session_of(request: Request) -> RobotSession:
        session: RobotSession = request.app.state.session
        return session

    def json_only(request: Request) -> None:
        if request.headers.get("content-type", "").split(";")[0].strip().lower() != "application/json":
            raise HTTPException(415, "Send JSON (Content-Type: application/json).")

    def authorised(request: Request) -> None:
        if not settings.requires_token:
            return
        given = request.headers.get(TOKEN_HEADER, "")
        auth = request.headers.get("authorization", "")
        if not given and auth.lower().startswith("bearer "):
            given = auth[7:].strip()
        if not (given and settings.token and secrets.compare_digest(given, settings.token)):
            raise HTTPException(401, "This langnav is reachable from other machines: moving the robot needs "
                                     "the token printed when it started (open the page with ?token=...).")

    def rate_limited(request: Request) -> None:
        client = request.client.host if request.client else "unknown"
        wait = limiter.check(client)
        if wait > 0:
            raise HTTPException(429, f"Too many requests: wait {wait:.1f} s and try again.",
                                headers={"Retry-After": str(max(1, round(wait + 0.5)))})

    moving = [Depends(json_only), Depends(authorised), Depends(rate_limited)]

    @app.get("/", include_in_schema=False)
    async def index() -> FileResponse:
        return FileResponse(STATIC_DIR / "index.html", media_type="text/html; charset=utf-8",
                            headers={"Cache-Control": "no-cache"})

    @app.get("/favicon.ico", include_in_schema=False)
    async def favicon() -> Response:
        return FileResponse(STATIC_DIR / "favicon.svg", media_type="image/svg+xml")

    app.mount("/static", StaticFiles(directory=STATIC_DIR), name="static")

    @app.get("/api/status")
    def status(request: Request) -> dict[str, Any]:
        return session_of(request).status()

    @app.get("/api/history")
    def history(request: Request, after: int = 0, limit: int = MAX_HISTORY_ROWS) -> dict[str, Any]:
        msgs = session_of(request).store.history(after_id=after, limit=limit)
        return {"messages": [m.to_json() for m in msgs]}

    @app.get("/api/spot")
    def spot(request: Request, x: float, y: float) -> dict[str, Any]:
        if not (math.isfinite(x) and math.isfinite(y)):
            raise HTTPException(422, "x and y must be finite numbers (map-frame metres).")
        return session_of(request).spot(x, y)

    @app.get("/api/places")
    def places(request: Request) -> dict[str, Any]:
        return {"places": session_of(request).places()}

    @app.post("/api/places", dependencies=moving)
    def name_place(body: PlaceIn, request: Request) -> dict[str, Any]:
        return session_of(request).name_place(body.name, body.x, body.y, body.element_id)

    @app.post("/api/places/rename", dependencies=moving)
    def rename_place(body: RenameIn, request: Request) -> dict[str, Any]:
        return session_of(request).rename_place(body.name, body.new_name)

    @app.post("/api/places/forget", dependencies=moving)
    def forget_place(body: ForgetIn, request: Request) -> dict[str, Any]:
        return session_of(request).forget_place(body.name)

    @app.get("/api/map.png")
    def map_png(request: Request) -> Response:
        return Response(session_of(request).map_png(), media_type="image/png")

    @app.post("/api/prompt", dependencies=moving)
    def prompt(body: PromptIn, request: Request) -> dict[str, Any]:
        if len(body.text) > settings.max_prompt_chars:
            raise HTTPException(413, f"The prompt is {len(body.text)} characters long; langnav reads at most "
                                     f"{settings.max_prompt_chars}. Give the robot one instruction or a few steps.")
        msgs = session_of(request).submit_prompt(body.text, replace=body.replace)
        return {"messages": [m.to_json() for m in msgs]}

    @app.post("/api/goto", dependencies=moving)
    def goto(body: GotoIn, request: Request) -> dict[str, Any]:
        msgs = session_of(request).go_to(body.x, body.y, body.yaw_deg)
        return {"messages": [m.to_json() for m in msgs]}

    @app.post("/api/stop")
    async def stop(request: Request) -> dict[str, Any]:
        # Not threaded and not rate limited: the robot halts before anything else is done.
        return session_of(request).stop()

    @app.post("/api/pause")
    async def pause(request: Request) -> dict[str, Any]:
        return session_of(request).pause()

    @app.post("/api/resume", dependencies=moving)
    def resume(request: Request) -> dict[str, Any]:
        return session_of(request).resume()

    @app.post("/api/translator", dependencies=[Depends(json_only), Depends(authorised)])
    def translator(body: TranslatorIn, request: Request) -> dict[str, Any]:
        return session_of(request).set_translator(body.name)

    @app.websocket("/ws")
    async def stream(ws: WebSocket) -> None:
        session: RobotSession = ws.app.state.session
        origin = ws.headers.get("origin")
        if origin and urlsplit(origin).netloc != ws.headers.get("host"):
            await ws.close(code=1008, reason="other origins may not watch this robot")
            return
        if session.broadcaster.subscriber_count >= MAX_VIEWERS:
            await ws.close(code=1013, reason=f"too many viewers (at most {MAX_VIEWERS}); try again later")
            return
        await ws.accept()
        sub = session.broadcaster.subscribe()
        try:
            await ws.send_text(encode({"type": "hello", "status": session.status()}))
            receiver = asyncio.create_task(_drain(ws, sub))
            try:
                while not sub.closed:
                    batch = await sub.next_batch()
                    if sub.closed:
                        break
                    if not batch:
                        await ws.send_text('{"type":"ping"}')
                    for text in batch:
                        await ws.send_text(text)
            finally:
                receiver.cancel()
        except (WebSocketDisconnect, RuntimeError):
            pass
        finally:
            session.broadcaster.unsubscribe(sub)

    return app


async def _drain(ws: WebSocket, sub: Subscriber) -> None:
    """Read (and ignore) what the client sends, so a closed socket is noticed at once."""
    try:
        with contextlib.suppress(WebSocketDisconnect, RuntimeError):
            while True:
                await ws.receive_text()
    finally:
        sub.close()
