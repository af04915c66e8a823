"""Reading and writing maps: map_server YAML (+PGM/PNG), bare images, and map_saver output.

Map_server semantics (Nav2 ``nav2_map_server/src/map_io.cpp``):

* the pixel shade is the mean of its colour channels, in [0, 1];
* ``occ = 1 - shade`` (or ``shade`` when ``negate: 1``);
* ``trinary``: occ > occupied_thresh -> occupied, occ < free_thresh -> free, otherwise unknown;
* ``scale``: like trinary, but in-between values become 1..99 (and transparent pixels unknown);
  langnav then reduces them with the ROS thresholds of :func:`langnav.maps.grid.from_ros_data`;
* ``raw``: the pixel value *is* the ROS value (0..100; anything else unknown).
"""

from __future__ import annotations

import logging
import math
import re
from pathlib import Path
from typing import Any, Final

import numpy as np
import numpy.typing as npt
import yaml
from PIL import Image, UnidentifiedImageError

from langnav.maps.errors import MapError
from langnav.maps.grid import FREE, MAX_CELLS, OCCUPIED, UNKNOWN, OccupancyGrid, from_ros_data

log = logging.getLogger(__name__)

#: Bare images (IPA / ROSE² style): pixel >= this is free.
BARE_FREE_MIN: Final = 250
#: Bare images: pixel <= this is occupied; values between are unknown.
BARE_OCCUPIED_MAX: Final = 50
#: Resolution assumed for bare images when none is given (the IPA authors' 5 cm).
DEFAULT_BARE_RESOLUTION_M: Final = 0.05
#: map_saver's defaults, also used when a YAML omits a threshold.
DEFAULT_OCCUPIED_THRESH: Final = 0.65
DEFAULT_FREE_THRESH: Final = 0.25
#: free_thresh written by save_map: ROS map_saver's classic 0.196, so that the 205 it writes for
#: unknown (occ = 50/255 = 0.19608) reads back as unknown; with 0.25 it would read back as free.
SAVE_FREE_THRESH: Final = 0.196
MODES: Final = ("trinary", "scale", "raw")
#: The grey map_saver (and most SLAM tools) write for unknown cells: occupancy (255 - 205) / 255
#: = 0.19608, which reads as unknown only with free_thresh at most that (map_saver's 0.196) and
#: occupied_thresh above it; a YAML with free_thresh 0.25 (map_server's old default) reads it as
#: free, and the building stands in a field of free floor.
UNKNOWN_GREY: Final = 205
#: Longest YAML value quoted back in an error message.
SHOWN_MAX_CHARS: Final = 80
IMAGE_SUFFIXES: Final = (".pgm", ".png", ".bmp", ".jpg", ".jpeg", ".tif", ".tiff", ".gif")

# PIL refuses decompression bombs itself; keep its limit in line with ours.
Image.MAX_IMAGE_PIXELS = MAX_CELLS


def load_map(path: str | Path, resolution_m: float | None = None, unknown_grey: bool = False) -> OccupancyGrid:
    """Load a map_server YAML, or a bare image (with ``resolution_m``, default 0.05 m).

    ``unknown_grey``: read the grey ``UNKNOWN_GREY`` of a YAML map's image as unknown whatever
    its thresholds say (see :func:`load_map_yaml`).
    """
    p = Path(path)
    _require_file(p, "no such file", "is a directory; give a map .yaml or an image")
    if p.suffix.lower() in (".yaml", ".yml"):
        if resolution_m is not None:
            log.warning("%s: --resolution ignored, the YAML gives the resolution", p)
        return load_map_yaml(p, unknown_grey=unknown_grey)
    if p.suffix.lower() in IMAGE_SUFFIXES:
        return load_bare_image(p, resolution_m if resolution_m is not None else DEFAULT_BARE_RESOLUTION_M)
    raise MapError(f"{p}: unknown map type {p.suffix!r}; give a .yaml (map_server) or an image "
                   f"({', '.join(IMAGE_SUFFIXES)})")


def _require_file(path: Path, missing: str, directory: str) -> None:
    """Raise MapError unless ``path`` is an existing file (a name the OS refuses counts as missing)."""
    try:
        exists, is_dir = path.exists(), path.is_dir()
    except (OSError, ValueError) as exc:
        raise MapError(f"{_shown(str(path))}: cannot use this path: {exc.__class__.__name__}: "
                       f"{getattr(exc, 'strerror', None) or exc}") from exc
    if not exists:
        raise MapError(f"{path}: {missing}")
    if is_dir:
        raise MapError(f"{path}: {directory}")


def _read_yaml(path: Path) -> dict[str, Any]:
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise MapError(f"{path}: cannot read: {exc}") from exc
    try:
        doc = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise MapError(f"{path}: not valid YAML: {exc}") from exc
    if not isinstance(doc, dict):
        raise MapError(f"{path}: expected a YAML mapping with image, resolution and origin")
    return doc


#: A number YAML 1.1 (PyYAML) reads as a string but map_server's yaml-cpp reads as a number:
#: exponents without a dot or a sign ("5e-2", "1E3").
_YAML11_NUMBER: Final = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)[eE][+-]?\d+")


def _as_finite(val: Any) -> float | None:
    """``val`` as a finite float, or None: a bool, a non-number, NaN, an infinity or an integer
    too large for a float is no number here."""
    if isinstance(val, str) and _YAML11_NUMBER.fullmatch(val.strip()):
        val = float(val)
    if isinstance(val, bool) or not isinstance(val, int | float):
        return None
    try:
        out = float(val)
    except OverflowError:
        return None
    return out if math.isfinite(out) else None


def _shown(val: Any) -> str:
    """A YAML value for a message, cut short (a hostile file may hold a megabyte in one key)."""
    text = repr(val)
    return text if len(text) <= SHOWN_MAX_CHARS else text[:SHOWN_MAX_CHARS - 3] + "..."


def _number(path: Path, doc: dict[str, Any], key: str, default: float | None = None) -> float:
    if key not in doc:
        if default is None:
            raise MapError(f"{path}: missing required key {key!r}")
        return default
    val = _as_finite(doc[key])
    if val is None:
        raise MapError(f"{path}: {key} must be a finite number, got {_shown(doc[key])}")
    return val


def load_map_yaml(path: str | Path, unknown_grey: bool = False) -> OccupancyGrid:
    """Load a ROS map_server map (YAML + image), read as map_server reads it.

    When the YAML's thresholds read the unknown grey (``UNKNOWN_GREY``) that the image holds as
    free or occupied, a warning names the threshold and what to change. ``unknown_grey``: read
    that grey as unknown anyway (what the map's maker meant).
    """
    p = Path(path)
    doc = _read_yaml(p)
    image = doc.get("image")
    if not isinstance(image, str) or not image:
        raise MapError(f"{p}: missing or empty 'image' key")
    resolution = _number(p, doc, "resolution")
    origin = doc.get("origin")
    values = [_as_finite(v) for v in origin] if isinstance(origin, list) else []
    if len(values) not in (2, 3) or any(v is None for v in values):
        raise MapError(f"{p}: origin must be [x, y, yaw] (finite numbers: metres, metres, radians), "
                       f"got {_shown(origin)}")
    ox, oy = float(values[0] or 0.0), float(values[1] or 0.0)
    oyaw = float(values[2] or 0.0) if len(values) == 3 else 0.0
    negate = doc.get("negate", 0)
    if negate not in (0, 1, True, False):
        raise MapError(f"{p}: negate must be 0 or 1, got {_shown(negate)}")
    occ_th = _number(p, doc, "occupied_thresh", DEFAULT_OCCUPIED_THRESH)
    free_th = _number(p, doc, "free_thresh", DEFAULT_FREE_THRESH)
    if not (0.0 <= free_th < occ_th <= 1.0):
        raise MapError(f"{p}: need 0 <= free_thresh < occupied_thresh <= 1, got "
                       f"free_thresh={free_th}, occupied_thresh={occ_th}")
    mode = doc.get("mode", "trinary")
    if mode not in MODES:
        raise MapError(f"{p}: mode {_shown(mode)} is not one of {', '.join(MODES)}")
    img_path = Path(image) if Path(image).is_absolute() else p.parent / image
    pixels, alpha = _read_image(img_path)
    ros = _pixels_to_ros(pixels, alpha, mode=mode, negate=bool(negate), occ_th=occ_th, free_th=free_th)
    if mode != "raw":
        grey = np.rint(pixels * 255.0) == UNKNOWN_GREY
        if alpha is not None:
            grey &= alpha >= 1.0
        n_grey = int(np.count_nonzero(grey))
        if unknown_grey:
            ros[grey] = -1
        elif n_grey:
            message = grey_read_as_known(bool(negate), occ_th, free_th, n_grey, grey.size)
            if message:
                log.warning("%s: %s", p, message)
    h, w = ros.shape
    return from_ros_data(np.flipud(ros).reshape(-1), w, h, resolution, ox, oy, oyaw, source=str(p))


def grey_read_as_known(negate: bool, occ_th: float, free_th: float, n_grey: int, n_pixels: int) -> str | None:
    """What is wrong when thresholds read the unknown grey as free or occupied (None if they do
    not): the value, the share of the map it turns, and what to change."""
    occ = UNKNOWN_GREY / 255.0 if negate else 1.0 - UNKNOWN_GREY / 255.0
    share = f"{n_grey} cells ({100.0 * n_grey / max(n_pixels, 1):.0f} % of the map)"
    fix = "or pass --unknown-grey to read that grey as unknown"
    if occ < free_th:
        return (f"free_thresh {free_th:g} reads the grey {UNKNOWN_GREY} (unknown, as map_saver writes it; "
                f"occupancy {occ:.3f}) as FREE: {share} of unscanned space become free floor. If they are "
                f"unknown, set free_thresh to {SAVE_FREE_THRESH} (at most {occ:.4f}) in the YAML, {fix}.")
    if occ > occ_th:
        return (f"occupied_thresh {occ_th:g} (with negate: {int(negate)}) reads the grey {UNKNOWN_GREY} (unknown, "
                f"as map_saver writes it; occupancy {occ:.3f}) as OCCUPIED: {share} of unscanned space become "
                f"walls. If they are unknown, set occupied_thresh above {occ:.3f} or negate: 0 in the YAML, {fix}.")
    return None


def _read_image(path: Path) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64] | None]:
    """Pixel shades in [0, 1] (mean of colour channels) and alpha in [0, 1] if any, image orientation."""
    _require_file(path, "map image not found",
                  "the map image is a directory; the YAML's 'image' must name an image file")
    try:
        with Image.open(path) as im:
            im.load()
            bands = im.getbands()
            if im.mode in ("I", "I;16", "I;16B", "I;16L", "F"):
                arr = np.asarray(im, dtype=np.float64)
                # 16-bit PNGs and PGMs with maxval > 255 (which PIL scales to 0..65535) are 16-bit
                # whatever their largest value; only other wide images are judged by their values.
                sixteen = im.mode.startswith("I;16") or im.format in ("PPM", "PGM")
                top = 65535.0 if sixteen or arr.max(initial=0) > 255 else 255.0
                return np.clip(arr / top, 0, 1), None
            has_alpha = "A" in bands
            rgb = im.convert("RGBA" if has_alpha else ("RGB" if len(bands) >= 3 else "L"))
            arr = np.asarray(rgb, dtype=np.float64) / 255.0
    except Image.DecompressionBombError as exc:
        raise MapError(f"{path}: image is absurdly large ({exc})") from exc
    except UnidentifiedImageError as exc:
        raise MapError(f"{path}: not a readable image (bad or unknown header)") from exc
    except (OSError, SyntaxError, ValueError) as exc:
        raise MapError(f"{path}: broken image data: {exc}") from exc
    if arr.ndim == 2:
        return arr, None
    if has_alpha:
        return arr[..., :-1].mean(axis=2), arr[..., -1]
    return arr.mean(axis=2), None


def _pixels_to_ros(shade: npt.NDArray[np.float64], alpha: npt.NDArray[np.float64] | None, *, mode: str,
                   negate: bool, occ_th: float, free_th: float) -> npt.NDArray[np.int16]:
    """map_server's per-pixel rule -> ROS values (-1, 0..100), image orientation."""
    if mode == "raw":
        raw = np.rint(shade * 255.0).astype(np.int16)
        return np.where(raw <= 100, raw, -1).astype(np.int16)
    occ = shade if negate else 1.0 - shade
    out = np.full(shade.shape, -1, dtype=np.int16)
    out[occ > occ_th] = 100
    out[occ < free_th] = 0
    if mode == "scale":
        mid = (occ >= free_th) & (occ <= occ_th)
        out[mid] = np.rint((occ[mid] - free_th) / (occ_th - free_th) * 99.0).astype(np.int16)
        if alpha is not None:
            out[alpha < 1.0] = -1
    return out


def load_bare_image(path: str | Path, resolution_m: float = DEFAULT_BARE_RESOLUTION_M) -> OccupancyGrid:
    """A bare map image (IPA / ROSE² style): >= 250 free, <= 50 occupied, between unknown. Origin 0, 0."""
    p = Path(path)
    shade, alpha = _read_image(p)
    val = np.rint(shade * 255.0)
    cells = np.full(val.shape, UNKNOWN, dtype=np.int8)
    cells[val >= BARE_FREE_MIN] = FREE
    cells[val <= BARE_OCCUPIED_MAX] = OCCUPIED
    if alpha is not None:
        cells[alpha < 0.5] = UNKNOWN
    return OccupancyGrid(np.flipud(cells).copy(), float(resolution_m), 0.0, 0.0, 0.0, source=str(p))


def save_map(grid: OccupancyGrid, yaml_path: str | Path) -> tuple[Path, Path]:
    """Save as map_saver does: a trinary P5 PGM (0/205/254) beside a YAML. Returns both paths."""
    y = Path(yaml_path)
    if y.suffix.lower() not in (".yaml", ".yml"):
        y = y.with_suffix(".yaml")
    pgm = y.with_suffix(".pgm")
    y.parent.mkdir(parents=True, exist_ok=True)
    img = grid.to_image()
    header = f"P5\n# CREATOR: langnav {grid.resolution_m:.3f} m/pix\n{grid.width} {grid.height}\n255\n"
    pgm.write_bytes(header.encode("ascii") + img.tobytes())
    # Written line by line as map_saver does (origin as a one-line flow list: some readers,
    # the bench's referee among them, read the YAML line by line).
    ox, oy, oyaw = (float(grid.origin_x_m), float(grid.origin_y_m), float(grid.origin_yaw_rad))
    text = (
        f"image: {pgm.name}\n"
        "mode: trinary\n"
        f"resolution: {float(grid.resolution_m)!r}\n"
        f"origin: [{ox!r}, {oy!r}, {oyaw!r}]\n"
        "negate: 0\n"
        f"occupied_thresh: {DEFAULT_OCCUPIED_THRESH}\n"
        f"free_thresh: {SAVE_FREE_THRESH}\n"
    )
    y.write_text(text, encoding="utf-8")
    return y, pgm


__all__ = ["FREE", "OCCUPIED", "UNKNOWN", "UNKNOWN_GREY", "grey_read_as_known", "load_bare_image", "load_map",
           "load_map_yaml", "save_map"]
