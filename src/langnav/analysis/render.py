"""The picture a user looks at to trust the analysis: the map with every element drawn and named.

The grid is drawn in grey (free white, occupied black, unknown grey), rooms tinted by label,
hallways striped, obstacle cells and frontier cells coloured; on top: walls, corners, doors,
narrow passages, and each element's *name as a user would type it* ("door 2", "hallway 1"),
plus a scale bar and a legend.

Legible at any size:

- the picture covers the scanned part of the grid (plus a margin), not its unknown border;
- a cell is drawn as several pixels on small maps (about ``TARGET_PX_PER_M`` pixels a metre,
  the longer side at least ``TARGET_SIDE_PX``), and the PNG never exceeds ``MAX_PNG_PIXELS``
  (a huge grid is drawn with several cells to a pixel rather than failing);
- labels never overlap: placed greedily, most important first (spaces, doors, passages,
  unexplored areas, obstacles, corners, walls), next to their element or further out with a
  leader line; a label with no room left goes to the legend beside the map;
- ``save_svg`` writes the same picture as an SVG (the map as an embedded image, the elements and
  labels as vectors) that a browser zooms without limit: the way to read a large map.
"""

from __future__ import annotations

import base64
import io
import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Final, Protocol
from xml.sax.saxutils import escape

import numpy as np
import numpy.typing as npt
from PIL import Image, ImageDraw, ImageFont

from langnav.analysis.elements import ElementKind, MapAnalysis
from langnav.maps.grid import FREE, OCCUPIED

#: Small maps are drawn until the longer side has about this many pixels (readable labels).
TARGET_SIDE_PX: Final = 1200
#: ... and at least this many pixels a metre (a 1 m door about as wide as its label).
TARGET_PX_PER_M: Final = 40.0
#: Never more pixels a cell than this (a tiny test map would become a poster).
MAX_SCALE: Final = 10
#: The PNG holds at most this many pixels (about 75 MB of RGB while drawing): a larger map is
#: drawn at fewer pixels a cell, down to several cells a pixel, never failing.
MAX_PNG_PIXELS: Final = 25_000_000
#: SVG user units a metre: labels are small beside the rooms of a large map, and the reader zooms.
SVG_UNITS_PER_M: Final = 80.0
#: The picture covers the scanned cells plus this margin (the unknown border shows nothing).
CROP_MARGIN_M: Final = 1.0
FONT_SIZE_PX: Final = 13
#: Room left around a label's text (its white halo).
LABEL_PAD_PX: Final = 2
#: A label is tried beside its element, then on this many rings further out (with a leader line).
LABEL_RINGS: Final = 4
#: Label collision buckets (pixels): a label is checked only against labels in its buckets.
BUCKET_PX: Final = 64
LEGEND_WIDTH_PX: Final = 300
#: The legend lists at most this many labels that found no room; the rest are counted.
LEGEND_MAX_LINES: Final = 60
LINE_HEIGHT_PX: Final = 17

RGB = tuple[int, int, int]
GREY_FREE: Final[RGB] = (255, 255, 255)
GREY_OCCUPIED: Final[RGB] = (30, 30, 30)
GREY_UNKNOWN: Final[RGB] = (185, 185, 185)
#: Room tints: distinct light hues, cycled by label.
PALETTE: Final[tuple[RGB, ...]] = (
    (141, 211, 199), (190, 186, 218), (251, 128, 114), (128, 177, 211), (253, 180, 98),
    (179, 222, 105), (252, 205, 229), (188, 128, 189), (204, 235, 197), (255, 237, 111),
)
ROOM_TINT_ALPHA: Final = 0.35
#: Hallways are striped diagonally, stripes this many cells wide (darkened by HALLWAY_SHADE).
HALLWAY_STRIPE_CELLS: Final = 3
HALLWAY_SHADE: Final = 0.85
C_WALL: Final[RGB] = (30, 90, 220)
C_CORNER: Final[RGB] = (200, 0, 200)
C_DOOR: Final[RGB] = (0, 160, 0)
C_OBSTACLE: Final[RGB] = (235, 120, 0)
C_PASSAGE: Final[RGB] = (0, 170, 190)
C_FRONTIER: Final[RGB] = (220, 0, 0)
C_TEXT: Final[RGB] = (0, 0, 0)
C_HALO: Final[RGB] = (255, 255, 255)

#: Label priority (lower first) and colour per element kind.
_PRIORITY: Final = {ElementKind.ROOM: 0, ElementKind.HALLWAY: 0, ElementKind.DOOR: 1,
                    ElementKind.NARROW_PASSAGE: 2, ElementKind.UNEXPLORED: 3, ElementKind.OBSTACLE: 4,
                    ElementKind.CORNER: 5, ElementKind.WALL: 6}
#: The legend's key: what each colour means.
_KEY: Final[tuple[tuple[str, RGB], ...]] = (
    ("room / hallway (striped)", C_TEXT), ("door", C_DOOR), ("narrow passage", C_PASSAGE),
    ("unexplored area (frontier)", C_FRONTIER), ("obstacle", C_OBSTACLE), ("corner", C_CORNER),
    ("wall", C_WALL),
)

Box = tuple[float, float, float, float]
Point = tuple[float, float]


def display_name(element_id: str) -> str:
    """An element's name as a user types it: ``door_2`` -> ``door 2``."""
    return element_id.replace("_", " ")


@dataclass(frozen=True)
class Frame:
    """Where the grid lands in the picture: grid rows ``r0..r1`` and columns ``c0..c1`` (grid
    orientation, row 0 at the bottom), ``k`` cells to a block (1 unless the map is huge), and
    ``s`` picture units (pixels) a block."""

    r0: int
    r1: int
    c0: int
    c1: int
    k: int
    s: float

    @property
    def blocks(self) -> tuple[int, int]:
        """(rows, cols) of blocks."""
        return -(-(self.r1 - self.r0) // self.k), -(-(self.c1 - self.c0) // self.k)

    @property
    def size(self) -> tuple[int, int]:
        """(width, height) of the map part of the picture."""
        rows, cols = self.blocks
        return max(1, round(cols * self.s)), max(1, round(rows * self.s))

    def units_per_m(self, resolution_m: float) -> float:
        return self.s / (self.k * resolution_m)


def frame_for(analysis: MapAnalysis, units_per_m: float | None = None, max_pixels: int = MAX_PNG_PIXELS) -> Frame:
    """The frame of the picture: the scanned cells plus a margin; a whole number of pixels a
    cell chosen for legibility within ``max_pixels`` (PNG), or ``units_per_m`` (SVG)."""
    grid = analysis.grid
    known = grid.cells != -1
    rows = np.flatnonzero(known.any(axis=1))
    cols = np.flatnonzero(known.any(axis=0))
    margin = math.ceil(CROP_MARGIN_M / grid.resolution_m)
    if len(rows) == 0:
        r0, r1, c0, c1 = 0, grid.height, 0, grid.width
    else:
        r0, r1 = max(0, int(rows[0]) - margin), min(grid.height, int(rows[-1]) + 1 + margin)
        c0, c1 = max(0, int(cols[0]) - margin), min(grid.width, int(cols[-1]) + 1 + margin)
    h, w = r1 - r0, c1 - c0
    if units_per_m is not None:
        return Frame(r0, r1, c0, c1, 1, units_per_m * grid.resolution_m)
    s = max(1, TARGET_SIDE_PX // max(h, w), round(TARGET_PX_PER_M * grid.resolution_m))
    s = min(s, MAX_SCALE)
    while s > 1 and h * w * s * s > max_pixels:
        s -= 1
    k = 1
    while -(-h // k) * -(-w // k) > max_pixels:
        k += 1
    return Frame(r0, r1, c0, c1, k, float(s))


def _any_in_blocks(a: npt.NDArray[np.bool_], k: int) -> npt.NDArray[np.bool_]:
    """Per ``k`` x ``k`` block of ``a`` (edges padded with False): is any cell set?"""
    if k == 1:
        return a
    h, w = a.shape
    ph, pw = -(-h // k) * k, -(-w // k) * k
    p = np.zeros((ph, pw), dtype=bool)
    p[:h, :w] = a
    return np.asarray(p.reshape(ph // k, k, pw // k, k).any(axis=(1, 3)), dtype=bool)


def base_colours(analysis: MapAnalysis, frame: Frame) -> npt.NDArray[np.uint8]:
    """The map's colours, one RGB pixel a block (image orientation: north up)."""
    grid = analysis.grid
    win = (slice(frame.r0, frame.r1), slice(frame.c0, frame.c1))
    cells = grid.cells[win]
    k = frame.k
    occupied = _any_in_blocks(cells == OCCUPIED, k)
    free = _any_in_blocks(cells == FREE, k) & ~occupied
    labels = analysis.labels[win][::k, ::k] if k > 1 else analysis.labels[win]
    rgb = np.empty((*occupied.shape, 3), dtype=np.uint8)
    rgb[:] = GREY_UNKNOWN
    rgb[free] = GREY_FREE
    rgb[occupied] = GREY_OCCUPIED
    hallway = np.zeros(occupied.shape, dtype=bool)
    hallway_labels = [r.label for r in analysis.rooms if r.kind == ElementKind.HALLWAY]
    if analysis.rooms:
        n = max(r.label for r in analysis.rooms) + 1
        tint = np.zeros((n, 3), dtype=np.float64)
        has = np.zeros(n, dtype=bool)
        for room in analysis.rooms:
            tint[room.label] = PALETTE[(room.label - 1) % len(PALETTE)]
            has[room.label] = True
        lab = np.clip(labels, 0, n - 1)
        m = free & has[lab] & (labels < n)
        rgb[m] = np.rint((1 - ROOM_TINT_ALPHA) * rgb[m] + ROOM_TINT_ALPHA * tint[lab[m]]).astype(np.uint8)
        if hallway_labels:
            rr, cc = np.ogrid[:occupied.shape[0], :occupied.shape[1]]
            hallway = m & np.isin(labels, hallway_labels) & (((rr + cc) // HALLWAY_STRIPE_CELLS) % 2 == 0)
            rgb[hallway] = (rgb[hallway] * HALLWAY_SHADE).astype(np.uint8)

    def paint(xy: npt.NDArray[np.float64], colour: RGB) -> None:
        if len(xy) == 0:
            return
        r, c = grid.world_to_index(xy[:, 0], xy[:, 1])
        br, bc = (r - frame.r0) // k, (c - frame.c0) // k
        ok = (br >= 0) & (br < rgb.shape[0]) & (bc >= 0) & (bc < rgb.shape[1])
        rgb[br[ok], bc[ok]] = colour

    for o in analysis.obstacles:
        paint(np.asarray(o.cells_xy, dtype=float).reshape(-1, 2), C_OBSTACLE)
    for u in analysis.unexplored:
        paint(np.asarray(u.frontier, dtype=float).reshape(-1, 2), C_FRONTIER)
    return np.ascontiguousarray(np.flipud(rgb))


# -- label placement -----------------------------------------------------------------------------

@dataclass(frozen=True)
class LabelItem:
    """A label to place: its text, the point it names, its colour and priority (lower first)."""

    text: str
    anchor: Point
    colour: RGB
    priority: int
    centred: bool = False


@dataclass(frozen=True)
class PlacedLabel:
    """A label placed in the picture: its box (x0, y0, x1, y1) holds the text and its halo;
    ``leader`` when it sits away from its element (a line joins them)."""

    text: str
    box: Box
    anchor: Point
    colour: RGB
    leader: bool


def boxes_overlap(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


class _Boxes:
    """Placed boxes in buckets of ``BUCKET_PX``: overlap tests against nearby boxes only."""

    def __init__(self) -> None:
        self._b: dict[tuple[int, int], list[Box]] = {}

    def _keys(self, box: Box) -> Iterator[tuple[int, int]]:
        for bx in range(math.floor(box[0] / BUCKET_PX), math.floor(box[2] / BUCKET_PX) + 1):
            for by in range(math.floor(box[1] / BUCKET_PX), math.floor(box[3] / BUCKET_PX) + 1):
                yield bx, by

    def free(self, box: Box) -> bool:
        return not any(boxes_overlap(box, o) for key in self._keys(box) for o in self._b.get(key, ()))

    def add(self, box: Box) -> None:
        for key in self._keys(box):
            self._b.setdefault(key, []).append(box)


def _candidates(anchor: Point, w: float, h: float, centred: bool) -> Iterator[tuple[Box, bool]]:
    """Boxes for a w x h label near ``anchor``, nearest first: beside it, then on rings further
    out (those need a leader line)."""
    ax, ay = anchor
    gap = 4.0
    near: list[Point] = [(ax + gap, ay - h / 2), (ax - gap - w, ay - h / 2), (ax - w / 2, ay - gap - h),
                         (ax - w / 2, ay + gap)]
    if centred:
        near.insert(0, (ax - w / 2, ay - h / 2))
    for x, y in near:
        yield (x, y, x + w, y + h), False
    for ring in range(1, LABEL_RINGS + 1):
        d = ring * (h + 2 * gap)
        for i in range(8):
            a = math.pi * i / 4
            cx, cy = ax + d * math.cos(a), ay - d * math.sin(a)
            yield (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2), True


def place_labels(items: Sequence[LabelItem], size: tuple[int, int], measure: Callable[[str], tuple[float, float]],
                 reserved: Sequence[Box] = ()) -> tuple[list[PlacedLabel], list[LabelItem]]:
    """Greedy placement, most important first, of labels that never overlap each other or the
    ``reserved`` boxes and stay inside the picture (``size``: width, height). Returns the
    placed labels and the items that found no room."""
    taken = _Boxes()
    for b in reserved:
        taken.add(b)
    width, height = size
    placed: list[PlacedLabel] = []
    dropped: list[LabelItem] = []
    for item in sorted(items, key=lambda i: i.priority):
        tw, th = measure(item.text)
        w, h = tw + 2 * LABEL_PAD_PX, th + 2 * LABEL_PAD_PX
        for box, leader in _candidates(item.anchor, w, h, item.centred):
            if box[0] < 0 or box[1] < 0 or box[2] > width or box[3] > height or not taken.free(box):
                continue
            taken.add(box)
            placed.append(PlacedLabel(item.text, box, item.anchor, item.colour, leader))
            break
        else:
            dropped.append(item)
    return placed, dropped


def label_items(analysis: MapAnalysis, to_px: Callable[[float, float], Point]) -> list[LabelItem]:
    """One label per element, named as a user would type it, anchored where it is drawn."""
    out: list[LabelItem] = []

    def add(element_id: str, kind: ElementKind, at: Point, colour: RGB, centred: bool = False) -> None:
        out.append(LabelItem(display_name(element_id), to_px(*at), colour, _PRIORITY[kind], centred))

    for room in analysis.rooms:
        add(room.id, room.kind, room.centroid, C_TEXT, centred=True)
    for d in analysis.doors:
        add(d.id, ElementKind.DOOR, d.center, C_DOOR)
    for p in analysis.narrow_passages:
        add(p.id, ElementKind.NARROW_PASSAGE, p.center, C_PASSAGE)
    for u in analysis.unexplored:
        if len(u.frontier) == 0:
            continue
        at = u.centroid if u.interior else (float(u.frontier[len(u.frontier) // 2][0]),
                                            float(u.frontier[len(u.frontier) // 2][1]))
        add(u.id, ElementKind.UNEXPLORED, at, C_FRONTIER)
    for o in analysis.obstacles:
        add(o.id, ElementKind.OBSTACLE, o.centroid, C_OBSTACLE)
    for c in analysis.corners:
        add(c.id, ElementKind.CORNER, c.approach, C_CORNER)
    for w in analysis.walls:
        add(w.id, ElementKind.WALL, w.midpoint, C_WALL)
    return out


# -- drawing -------------------------------------------------------------------------------------

class _Canvas(Protocol):
    def line(self, a: Point, b: Point, colour: RGB, width: float) -> None: ...
    def circle(self, c: Point, radius: float, colour: RGB, fill: bool) -> None: ...
    def rect(self, box: Box, colour: RGB) -> None: ...
    def text(self, at: Point, text: str, colour: RGB, halo: bool) -> None: ...


class _PilCanvas:
    def __init__(self, img: Image.Image, font: ImageFont.FreeTypeFont | ImageFont.ImageFont) -> None:
        self.draw = ImageDraw.Draw(img)
        self.font = font

    def line(self, a: Point, b: Point, colour: RGB, width: float) -> None:
        self.draw.line([a, b], fill=colour, width=max(1, round(width)))

    def circle(self, c: Point, radius: float, colour: RGB, fill: bool) -> None:
        box = [c[0] - radius, c[1] - radius, c[0] + radius, c[1] + radius]
        if fill:
            self.draw.ellipse(box, fill=colour)
        else:
            self.draw.ellipse(box, outline=colour, width=2)

    def rect(self, box: Box, colour: RGB) -> None:
        self.draw.rectangle([box[0], box[1], max(box[0], box[2]), max(box[1], box[3])], fill=colour)

    def text(self, at: Point, text: str, colour: RGB, halo: bool) -> None:
        if halo:
            self.draw.text(at, text, fill=colour, font=self.font, stroke_width=LABEL_PAD_PX, stroke_fill=C_HALO)
        else:
            self.draw.text(at, text, fill=colour, font=self.font)


def _hex(c: RGB) -> str:
    return f"#{c[0]:02x}{c[1]:02x}{c[2]:02x}"


class _SvgCanvas:
    def __init__(self, measure: Callable[[str], tuple[float, float]]) -> None:
        self.parts: list[str] = []
        self.measure = measure

    def line(self, a: Point, b: Point, colour: RGB, width: float) -> None:
        self.parts.append(f'<line x1="{a[0]:.1f}" y1="{a[1]:.1f}" x2="{b[0]:.1f}" y2="{b[1]:.1f}" '
                          f'stroke="{_hex(colour)}" stroke-width="{max(1.0, width):.1f}"/>')

    def circle(self, c: Point, radius: float, colour: RGB, fill: bool) -> None:
        paint = f'fill="{_hex(colour)}"' if fill else f'fill="none" stroke="{_hex(colour)}" stroke-width="2"'
        self.parts.append(f'<circle cx="{c[0]:.1f}" cy="{c[1]:.1f}" r="{radius:.1f}" {paint}/>')

    def rect(self, box: Box, colour: RGB) -> None:
        self.parts.append(f'<rect x="{box[0]:.1f}" y="{box[1]:.1f}" width="{box[2] - box[0]:.1f}" '
                          f'height="{box[3] - box[1]:.1f}" fill="{_hex(colour)}"/>')

    def text(self, at: Point, text: str, colour: RGB, halo: bool) -> None:
        # The text is stretched to the width measured for its box, so that placement holds
        # whatever font the viewer has.
        w, _h = self.measure(text)
        halo_attr = (f' stroke="{_hex(C_HALO)}" stroke-width="{2 * LABEL_PAD_PX}" paint-order="stroke"'
                     if halo else "")
        self.parts.append(f'<text x="{at[0]:.1f}" y="{at[1] + FONT_SIZE_PX * 0.85:.1f}" '
                          f'font-family="sans-serif" font-size="{FONT_SIZE_PX}" textLength="{w:.1f}" '
                          f'lengthAdjust="spacingAndGlyphs" fill="{_hex(colour)}"{halo_attr}>'
                          f"{escape(text)}</text>")


def _font() -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    return ImageFont.load_default(size=FONT_SIZE_PX)


def _measurer(font: ImageFont.FreeTypeFont | ImageFont.ImageFont) -> Callable[[str], tuple[float, float]]:
    def measure(text: str) -> tuple[float, float]:
        left, _top, right, _bottom = font.getbbox(text)
        return float(right - left), float(FONT_SIZE_PX)
    return measure


@dataclass(frozen=True)
class Layout:
    """Everything drawn, in picture units: the frame, the labels placed and those left to the
    legend, the scale bar's box, and the total size (map plus legend)."""

    frame: Frame
    labels: tuple[PlacedLabel, ...]
    dropped: tuple[LabelItem, ...]
    scale_bar: tuple[float, Box]
    size: tuple[int, int]


def _scale_bar(units_per_m: float, map_size: tuple[int, int]) -> tuple[float, Box]:
    """A round length (1, 2, 5, 10 ... m) about a sixth of the map's width, and its box
    (bottom left)."""
    target_m = max(map_size[0] / 6 / units_per_m, 1e-6)
    exp = 10 ** math.floor(math.log10(target_m))
    length_m = max(m * exp for m in (1, 2, 5) if m * exp <= max(target_m, exp))
    x0, y0 = 10.0, map_size[1] - 14.0
    x1 = x0 + length_m * units_per_m
    return length_m, (x0 - 2, y0 - 16, x1 + 40, y0 + 6)


def layout(analysis: MapAnalysis, frame: Frame, measure: Callable[[str], tuple[float, float]]) -> Layout:
    """Place the labels of ``analysis`` in ``frame``; see :func:`place_labels`."""
    size = frame.size
    units_per_m = frame.units_per_m(analysis.grid.resolution_m)
    bar = _scale_bar(units_per_m, size)
    to_px = _to_px(analysis, frame)
    placed, dropped = place_labels(label_items(analysis, to_px), size, measure, reserved=[bar[1]])
    legend_lines = 3 + len(_KEY) + min(len(dropped), LEGEND_MAX_LINES) + 1
    total = (size[0] + LEGEND_WIDTH_PX, max(size[1], legend_lines * LINE_HEIGHT_PX + 20))
    return Layout(frame, tuple(placed), tuple(dropped), bar, total)


def _to_px(analysis: MapAnalysis, frame: Frame) -> Callable[[float, float], Point]:
    grid = analysis.grid
    per_cell = frame.s / frame.k

    def to_px(x_m: float, y_m: float) -> Point:
        r, c = grid.world_to_cell(x_m, y_m)
        return (float(c) - frame.c0) * per_cell, (frame.r1 - float(r)) * per_cell
    return to_px


def _draw_elements(canvas: _Canvas, analysis: MapAnalysis, frame: Frame) -> None:
    """Walls, doors, passages and corners as lines and marks."""
    to_px = _to_px(analysis, frame)
    lw = max(1.0, frame.s / frame.k / 2)
    for w in analysis.walls:
        canvas.line(to_px(*w.start), to_px(*w.end), C_WALL, lw + 1)
    for d in analysis.doors:
        canvas.line(to_px(*d.jambs[0]), to_px(*d.jambs[1]), C_DOOR, lw + 3)
        canvas.circle(to_px(*d.center), 3, C_DOOR, fill=True)
    for p in analysis.narrow_passages:
        canvas.line(to_px(*p.ends[0]), to_px(*p.ends[1]), C_PASSAGE, lw + 2)
    for c in analysis.corners:
        x, y = to_px(*c.point)
        canvas.circle((x, y), 4, C_CORNER, fill=False)
        canvas.line((x, y), to_px(*c.approach), C_CORNER, 1)


def _draw_labels(canvas: _Canvas, lay: Layout) -> None:
    for lab in lay.labels:
        x0, y0, x1, y1 = lab.box
        if lab.leader:
            # From the element to the nearest point of the box.
            nx = min(max(lab.anchor[0], x0), x1)
            ny = min(max(lab.anchor[1], y0), y1)
            canvas.line(lab.anchor, (nx, ny), lab.colour, 1)
        canvas.text((x0 + LABEL_PAD_PX, y0 + LABEL_PAD_PX), lab.text, lab.colour, halo=True)


def _draw_scale_bar(canvas: _Canvas, lay: Layout, units_per_m: float) -> None:
    length_m, box = lay.scale_bar
    x0, y0 = box[0] + 2, box[3] - 6
    x1 = x0 + length_m * units_per_m
    canvas.rect(box, C_HALO)
    canvas.line((x0, y0), (x1, y0), C_TEXT, 3)
    canvas.line((x0, y0 - 5), (x0, y0 + 5), C_TEXT, 2)
    canvas.line((x1, y0 - 5), (x1, y0 + 5), C_TEXT, 2)
    canvas.text((x0, y0 - 16), f"{length_m:g} m", C_TEXT, halo=False)


def _draw_legend(canvas: _Canvas, lay: Layout) -> None:
    """The key of colours, then the names that found no room on the map."""
    x = lay.frame.size[0] + 12.0
    canvas.rect((float(lay.frame.size[0]), 0.0, float(lay.size[0]), float(lay.size[1])), C_HALO)
    y = 8.0
    canvas.text((x, y), "Legend", C_TEXT, halo=False)
    y += LINE_HEIGHT_PX
    for name, colour in _KEY:
        canvas.rect((x, y + 3, x + 10, y + 13), colour)
        canvas.text((x + 16, y), name, C_TEXT, halo=False)
        y += LINE_HEIGHT_PX
    if lay.dropped:
        y += LINE_HEIGHT_PX / 2
        canvas.text((x, y), f"Not labelled on the map ({len(lay.dropped)}):", C_TEXT, halo=False)
        y += LINE_HEIGHT_PX
        for item in lay.dropped[:LEGEND_MAX_LINES]:
            canvas.text((x + 8, y), item.text, item.colour, halo=False)
            y += LINE_HEIGHT_PX
        if len(lay.dropped) > LEGEND_MAX_LINES:
            canvas.text((x + 8, y), f"... and {len(lay.dropped) - LEGEND_MAX_LINES} more (see --json)",
                        C_TEXT, halo=False)


@dataclass(frozen=True)
class Picture:
    """A rendered PNG picture and its layout (label boxes, for tests and callers)."""

    image: Image.Image
    layout: Layout


def render_picture(analysis: MapAnalysis, max_pixels: int = MAX_PNG_PIXELS) -> Picture:
    """The annotated picture of an analysis (RGB, north up) with its layout."""
    frame = frame_for(analysis, max_pixels=max_pixels)
    font = _font()
    lay = layout(analysis, frame, _measurer(font))
    base = base_colours(analysis, frame)
    s = frame.s
    if s > 1:
        base = np.repeat(np.repeat(base, int(s), axis=0), int(s), axis=1)
    img = Image.new("RGB", lay.size, C_HALO)
    img.paste(Image.fromarray(base, mode="RGB"), (0, 0))
    canvas = _PilCanvas(img, font)
    _draw_elements(canvas, analysis, frame)
    _draw_labels(canvas, lay)
    _draw_scale_bar(canvas, lay, frame.units_per_m(analysis.grid.resolution_m))
    _draw_legend(canvas, lay)
    return Picture(img, lay)


def render_analysis(analysis: MapAnalysis) -> Image.Image:
    """The annotated picture of an analysis (RGB, image orientation: north up)."""
    return render_picture(analysis).image


def svg_text(analysis: MapAnalysis, units_per_m: float = SVG_UNITS_PER_M) -> tuple[str, Layout]:
    """The picture as SVG: the map's cells as an embedded PNG (one pixel a cell, scaled without
    smoothing), elements and labels as vectors. Returns the document and its layout."""
    frame = frame_for(analysis, units_per_m=units_per_m)
    measure = _measurer(_font())
    lay = layout(analysis, frame, measure)
    buf = io.BytesIO()
    Image.fromarray(base_colours(analysis, frame), mode="RGB").save(buf, format="PNG", optimize=True)
    data = base64.b64encode(buf.getvalue()).decode("ascii")
    mw, mh = frame.size
    canvas = _SvgCanvas(measure)
    _draw_elements(canvas, analysis, frame)
    _draw_labels(canvas, lay)
    _draw_scale_bar(canvas, lay, frame.units_per_m(analysis.grid.resolution_m))
    _draw_legend(canvas, lay)
    w, h = lay.size
    head = (f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
            f'width="{w}" height="{h}" viewBox="0 0 {w} {h}">\n'
            f'<rect width="{w}" height="{h}" fill="{_hex(C_HALO)}"/>\n'
            f'<image x="0" y="0" width="{mw}" height="{mh}" preserveAspectRatio="none" '
            f'style="image-rendering:pixelated" image-rendering="optimizeSpeed" '
            f'xlink:href="data:image/png;base64,{data}"/>\n')
    return head + "\n".join(canvas.parts) + "\n</svg>\n", lay


def save_png(analysis: MapAnalysis, path: str | Path) -> Path:
    """Render and write the picture; returns the path written."""
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    render_picture(analysis).image.save(p, format="PNG")
    return p


def save_svg(analysis: MapAnalysis, path: str | Path) -> Path:
    """Write the picture as SVG (zoomable: the way to read a large map); returns the path."""
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(svg_text(analysis)[0], encoding="utf-8")
    return p


def image_array(analysis: MapAnalysis) -> npt.NDArray[np.uint8]:
    """The picture as an (H, W, 3) uint8 array (for the web app or tests)."""
    return np.asarray(render_analysis(analysis), dtype=np.uint8)
