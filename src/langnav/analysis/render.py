"""The picture a user looks at to trust the analysis: the map with every element drawn and named.

The grid is drawn in grey (free white, occupied black, unknown grey), rooms tinted by label,
hallways striped, and on top: walls, corners, doors, obstacles, narrow passages, unexplored
areas with their frontier, each labelled with its id, plus a scale bar. Small maps are scaled
up by an integer factor so the labels stay readable.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Final

import numpy as np
import numpy.typing as npt
from PIL import Image, ImageDraw, ImageFont

from langnav.analysis.elements import ElementKind, MapAnalysis
from langnav.maps.grid import FREE, OCCUPIED

#: Scale small maps up until the longer side has about this many pixels (readable labels).
TARGET_SIDE_PX: Final = 1200
#: Never scale up more than this (a tiny test map would become a poster).
MAX_SCALE: Final = 10
FONT_SIZE_PX: Final = 13

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
HALLWAY_STRIPE_PX: Final = 6
C_WALL: Final[RGB] = (30, 90, 220)
C_CORNER: Final[RGB] = (200, 0, 200)
C_DOOR: Final[RGB] = (0, 160, 0)
C_OBSTACLE: Final[RGB] = (235, 120, 0)
C_PASSAGE: Final[RGB] = (0, 170, 190)
C_FRONTIER: Final[RGB] = (220, 0, 0)
C_TEXT: Final[RGB] = (0, 0, 0)


def _scale_for(width: int, height: int) -> int:
    return max(1, min(MAX_SCALE, TARGET_SIDE_PX // max(width, height, 1)))


def render_analysis(analysis: MapAnalysis) -> Image.Image:
    """The annotated picture of an analysis (RGB, image orientation: north up)."""
    grid = analysis.grid
    s = _scale_for(grid.width, grid.height)
    cells = np.flipud(grid.cells)
    labels = np.flipud(analysis.labels)
    rgb = np.empty((*cells.shape, 3), dtype=np.float64)
    rgb[:] = GREY_UNKNOWN
    rgb[cells == FREE] = GREY_FREE
    rgb[cells == OCCUPIED] = GREY_OCCUPIED
    hallway_labels = {r.label for r in analysis.rooms if r.kind == ElementKind.HALLWAY}
    for room in analysis.rooms:
        tint = np.array(PALETTE[(room.label - 1) % len(PALETTE)], dtype=float)
        m = (labels == room.label) & (cells == FREE)
        rgb[m] = (1 - ROOM_TINT_ALPHA) * rgb[m] + ROOM_TINT_ALPHA * tint
    img_arr = np.repeat(np.repeat(rgb.round().astype(np.uint8), s, axis=0), s, axis=1)
    if hallway_labels:
        # Diagonal stripes over hallways, at image resolution.
        big = np.repeat(np.repeat(np.isin(labels, list(hallway_labels)) & (cells == FREE), s, 0), s, 1)
        yy, xx = np.indices(big.shape)
        stripe = big & (((xx + yy) // HALLWAY_STRIPE_PX) % 2 == 0)
        img_arr[stripe] = (img_arr[stripe] * 0.85).astype(np.uint8)
    img = Image.fromarray(img_arr, mode="RGB")
    draw = ImageDraw.Draw(img)
    font = ImageFont.load_default(size=FONT_SIZE_PX)

    def px(x_m: float, y_m: float) -> tuple[float, float]:
        r, c = grid.world_to_cell(x_m, y_m)
        return float(c) * s, (grid.height - float(r)) * s

    def label(xy: tuple[float, float], text: str, colour: RGB) -> None:
        draw.text((xy[0] + 3, xy[1] + 1), text, fill=colour, font=font, stroke_width=2,
                  stroke_fill=(255, 255, 255))

    lw = max(1, s // 2)
    for u in analysis.unexplored:
        for fx, fy in u.frontier:
            x, y = px(float(fx), float(fy))
            draw.rectangle([x - s / 2, y - s / 2, x + s / 2, y + s / 2], fill=C_FRONTIER)
        if len(u.frontier):
            anchor = px(*u.centroid) if u.interior else px(*map(float, u.frontier[len(u.frontier) // 2]))
            label(anchor, f"{u.id} {u.area_m2:.1f}m2" + ("" if u.interior else " (outside)"), C_FRONTIER)
    for room in analysis.rooms:
        label(px(*room.centroid), f"{room.id} {room.area_m2:.1f}m2", C_TEXT)
    for w in analysis.walls:
        a, b = px(*w.start), px(*w.end)
        draw.line([a, b], fill=C_WALL, width=lw + 1)
        mx, my = px(*w.midpoint)
        ix, iy = w.inward
        label((mx + ix * 6, my - iy * 6 - 6), w.id, C_WALL)
    for o in analysis.obstacles:
        for ox, oy in o.cells_xy:
            x, y = px(float(ox), float(oy))
            draw.rectangle([x - s / 2, y - s / 2, x + s / 2 - 1, y + s / 2 - 1], fill=C_OBSTACLE)
        label(px(*o.centroid), o.id, C_OBSTACLE)
    for d in analysis.doors:
        a, b = px(*d.jambs[0]), px(*d.jambs[1])
        draw.line([a, b], fill=C_DOOR, width=lw + 3)
        cx, cy = px(*d.center)
        draw.ellipse([cx - 3, cy - 3, cx + 3, cy + 3], fill=C_DOOR)
        label((cx, cy), f"{d.id} {d.width_m:.2f}m", C_DOOR)
    for p in analysis.narrow_passages:
        a, b = px(*p.ends[0]), px(*p.ends[1])
        draw.line([a, b], fill=C_PASSAGE, width=lw + 2)
        label(px(*p.center), f"{p.id} {p.width_m:.2f}m", C_PASSAGE)
    for c in analysis.corners:
        x, y = px(*c.point)
        draw.ellipse([x - 4, y - 4, x + 4, y + 4], outline=C_CORNER, width=2)
        ax, ay = px(*c.approach)
        draw.line([(x, y), (ax, ay)], fill=C_CORNER, width=1)
        label((ax, ay), c.id, C_CORNER)
    _scale_bar(draw, font, grid.resolution_m, s, img.height)
    return img


def _scale_bar(draw: ImageDraw.ImageDraw, font: ImageFont.ImageFont | ImageFont.FreeTypeFont,
               resolution_m: float, s: int, height_px: int) -> None:
    """A bar of a round length (1, 2, 5, 10 ... m) about a sixth of the picture wide, bottom left."""
    px_per_m = s / resolution_m
    target_m = draw.im.size[0] / 6 / px_per_m
    exp = 10 ** math.floor(math.log10(max(target_m, 1e-6)))
    length_m = max(m * exp for m in (1, 2, 5) if m * exp <= max(target_m, exp))
    x0, y0 = 10, height_px - 14
    x1 = x0 + length_m * px_per_m
    draw.rectangle([x0 - 2, y0 - 16, x1 + 40, y0 + 6], fill=(255, 255, 255))
    draw.line([(x0, y0), (x1, y0)], fill=C_TEXT, width=3)
    draw.line([(x0, y0 - 5), (x0, y0 + 5)], fill=C_TEXT, width=2)
    draw.line([(x1, y0 - 5), (x1, y0 + 5)], fill=C_TEXT, width=2)
    draw.text((x0, y0 - 16), f"{length_m:g} m", fill=C_TEXT, font=font)


def save_png(analysis: MapAnalysis, path: str | Path) -> Path:
    """Render and write the picture; returns the path written."""
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    render_analysis(analysis).save(p, format="PNG")
    return p


def image_array(analysis: MapAnalysis) -> npt.NDArray[np.uint8]:
    """The picture as an (H, W, 3) uint8 array (for the web app or tests)."""
    return np.asarray(render_analysis(analysis), dtype=np.uint8)
