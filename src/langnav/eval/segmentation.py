"""Room-segmentation and doorway-detection metrics of the IPA / ROSE² benchmarks.

Room segmentation (Bormann et al., ICRA 2016, ``evaluation_segmentation.cpp``; ROSE², RA-L 2022):
for every ground-truth room, *recall* is its largest overlap with one segment divided by the
room's area; for every segment, *precision* is its largest overlap with one room divided by the
segment's area. Both are counted on the annotated floor only (the cells of some ground-truth
room); rooms and segments of at most ``MIN_REGION_PX`` pixels there are ignored; the figures are
the means over rooms and over segments ("micro" in the authors' tables).

Doorways (IPA Voronoi-random-field training maps): each ground-truth doorway is a blob of pixel
value ``IPA_DOORWAY_VALUE``; a detected door matches the nearest unmatched blob within
``DOOR_MATCH_TOLERANCE_M`` of its centre (one to one, closest pairs first). A doorway's width is
its clear width in the map, from jamb to jamb (:func:`doorway_clear_width_m`), not the size of
the blob painted over it (the blobs are painted well past the jambs: office_e's 0.25-0.4 m
drawn doors carry 0.7-1.1 m blobs).

All arrays here are in image orientation (row 0 = top), as the benchmark files are.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

#: Rooms and segments of at most this many pixels are ignored (the authors' rule).
MIN_REGION_PX: Final = 100
#: IPA ground truth: pixels brighter than this are room floor (``cv::threshold(gt, 250)``).
IPA_GT_FLOOR_MIN: Final = 250
#: IPA training maps: doorway pixels have this value (77 room, 115 hallway).
IPA_DOORWAY_VALUE: Final = 179
#: Doorway blobs smaller than this many pixels are stray pixels of the painting.
IPA_DOORWAY_MIN_PX: Final = 20
#: A detected door counts when its centre is within this distance of a labelled doorway blob:
#: about half a door width, so a detection cannot be credited to the neighbouring doorway.
DOOR_MATCH_TOLERANCE_M: Final = 0.5
#: A doorway's jambs are the pieces of wall within this many pixels of its blob (the painting
#: stops a pixel or two short of the walls, or runs over them).
DOORWAY_JAMB_PAD_PX: Final = 2
#: Openings under one blob narrower than this (m) are cracks between two pieces of one wall, not
#: doorways of their own (the narrowest drawn doors, office_e's, are 0.25 m).
DOORWAY_MIN_CLEAR_M: Final = 0.25

IntImage = npt.NDArray[np.int32]


@dataclass(frozen=True)
class PrecisionRecall:
    precision: float
    recall: float
    n_predicted: int
    n_truth: int

    @property
    def f1(self) -> float:
        s = self.precision + self.recall
        return 2 * self.precision * self.recall / s if s > 0 else 0.0


def ipa_gt_rooms(gt_image: npt.NDArray[np.uint8]) -> IntImage:
    """IPA ground truth image -> room labels: 8-connected components of pixels > 250."""
    lab, _ = ndi.label(gt_image > IPA_GT_FLOOR_MIN, structure=np.ones((3, 3), dtype=bool))
    return np.asarray(lab, dtype=np.int32)


def colour_gt_rooms(gt_rgb: npt.NDArray[np.uint8]) -> IntImage:
    """ROSE² ground truth (one RGB colour per room, black = not a room) -> room labels."""
    rgb = gt_rgb[..., :3].astype(np.int64)
    key = (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]
    uniq, inv = np.unique(key, return_inverse=True)
    lab = inv.reshape(key.shape).astype(np.int32)
    if uniq[0] == 0:  # black is not a room
        return lab
    return lab + 1


def room_precision_recall(gt_labels: IntImage, seg_labels: IntImage,
                          min_px: int = MIN_REGION_PX) -> PrecisionRecall:
    """The IPA / ROSE² room metric (module doc). Arrays must have the same shape."""
    if gt_labels.shape != seg_labels.shape:
        raise ValueError(f"ground truth {gt_labels.shape} and segmentation {seg_labels.shape} differ "
                         f"in shape; crop both to their common size first")
    on_floor = gt_labels > 0
    g = gt_labels[on_floor].astype(np.int64)
    s = seg_labels[on_floor].astype(np.int64)
    ng, ns = int(g.max(initial=0)) + 1, int(s.max(initial=0)) + 1
    g_area = np.bincount(g, minlength=ng)
    s_area = np.bincount(s, minlength=ns)
    overlap = np.bincount(g * ns + s, minlength=ng * ns).reshape(ng, ns)
    overlap[:, 0] = 0  # unsegmented floor overlaps no segment
    rooms = np.flatnonzero(g_area > min_px)
    rooms = rooms[rooms > 0]
    segs = np.flatnonzero(s_area > min_px)
    segs = segs[segs > 0]
    if rooms.size == 0:
        raise ValueError("the ground truth has no room larger than the minimum size")
    recall = float(np.mean(overlap[np.ix_(rooms, segs)].max(axis=1, initial=0) / g_area[rooms]))
    if segs.size == 0:
        return PrecisionRecall(0.0, recall, 0, int(rooms.size))
    precision = float(np.mean(overlap[np.ix_(rooms, segs)].max(axis=0) / s_area[segs]))
    return PrecisionRecall(precision, recall, int(segs.size), int(rooms.size))


def ipa_doorway_blobs(training_image: npt.NDArray[np.uint8]) -> list[npt.NDArray[np.int64]]:
    """(row, col) pixel arrays of the labelled doorways of an IPA training map."""
    lab, _n = ndi.label(training_image == IPA_DOORWAY_VALUE, structure=np.ones((3, 3), dtype=bool))
    blobs = []
    for i, sl in enumerate(ndi.find_objects(lab), start=1):
        if sl is None:
            continue
        rr, cc = np.nonzero(lab[sl] == i)
        if rr.size >= IPA_DOORWAY_MIN_PX:
            blobs.append(np.column_stack([rr + sl[0].start, cc + sl[1].start]))
    return blobs


@dataclass(frozen=True)
class Doorway:
    """One labelled doorway: its pixels ((row, col), image orientation) and its clear width (m)
    from jamb to jamb in the map (None where it has no two jambs to measure from)."""

    pixels: npt.NDArray[np.int64]
    clear_width_m: float | None


def _wall_pieces(blob: npt.NDArray[np.int64], occupied: npt.NDArray[np.bool_], whole: IntImage,
                 whole_size: npt.NDArray[np.int64], pad_px: int) -> list[npt.NDArray[np.int64]]:
    """The pieces of wall a doorway blob is cut in: the occupied pieces within ``pad_px`` of it
    (in a window around it) that belong to the largest structures there (the building's walls;
    not a table or a stray pixel beside the door), as (row, col) pixel arrays in image
    coordinates, ordered along the blob's long axis."""
    r0, c0 = np.maximum(blob.min(axis=0) - pad_px - 1, 0)
    r1, c1 = blob.max(axis=0) + pad_px + 2
    win = occupied[r0:r1, c0:c1]
    near = np.zeros(win.shape, dtype=bool)
    near[blob[:, 0] - r0, blob[:, 1] - c0] = True
    near = ndi.binary_dilation(near, iterations=pad_px)
    pieces, _ = ndi.label(win, structure=np.ones((3, 3), dtype=bool))
    ids = [int(i) for i in np.unique(pieces[near & win]) if i]
    sub = whole[r0:r1, c0:c1]
    size = {i: (int(whole_size[sub[pieces == i][0]]), int((pieces == i).sum())) for i in ids}
    ranked = sorted(ids, key=lambda i: size[i], reverse=True)
    # The two largest are the jambs; a further piece counts when its structure is as large as
    # the smaller jamb's (a wall between two doors), not a smaller thing standing by.
    keep = ranked[:2] + [i for i in ranked[2:] if size[i][0] >= size[ranked[1]][0]]
    walls = [np.argwhere(pieces == i) + np.array([r0, c0]) for i in keep]
    centred = blob.astype(float) - blob.mean(axis=0)
    axis = np.linalg.eigh(centred.T @ centred)[1][:, -1] if len(blob) > 1 else np.array([0.0, 1.0])
    return sorted(walls, key=lambda w: float(((w.astype(float) - blob.mean(axis=0)) @ axis).mean()))


def _gap(a: npt.NDArray[np.int64], b: npt.NDArray[np.int64]) -> tuple[float, npt.NDArray[np.float64]]:
    """The distance (pixels, between centres) of the nearest pixels of ``a`` and ``b``, and the
    midpoint of that pair."""
    d = np.sqrt(((a[:, None, :].astype(float) - b[None, :, :].astype(float)) ** 2).sum(axis=2))
    i, j = np.unravel_index(int(np.argmin(d)), d.shape)
    return float(d[i, j]), (a[i] + b[j]) / 2.0


def _walled_between(occupied: npt.NDArray[np.bool_], a: npt.NDArray[np.float64], b: npt.NDArray[np.float64]) -> bool:
    """Whether the straight line from pixel ``a`` to pixel ``b`` crosses an occupied pixel."""
    n = max(2, math.ceil(2 * float(np.hypot(*(b - a)))) + 1)
    t = np.linspace(0.0, 1.0, n)[:, None]
    rc = np.rint(a + t * (b - a)).astype(np.int64)
    return bool(occupied[rc[:, 0], rc[:, 1]].any())


def ipa_doorways(blobs: list[npt.NDArray[np.int64]], occupied: npt.NDArray[np.bool_], resolution_m: float,
                 min_width_m: float = DOORWAY_MIN_CLEAR_M, pad_px: int = DOORWAY_JAMB_PAD_PX) -> list[Doorway]:
    """The labelled doorways of an IPA map, each with its clear width in the map (``occupied``:
    the map's occupied pixels). A blob is painted over a doorway and past its jambs; where one
    blob covers two or more openings side by side (a wall piece between them parting two rooms:
    office_h paints one blob over each pair of office doors), each opening at least
    ``min_width_m`` wide is a doorway of its own, holding the blob's pixels nearest to it."""
    whole, _ = ndi.label(occupied, structure=np.ones((3, 3), dtype=bool))
    whole_size = np.bincount(whole.ravel())
    out: list[Doorway] = []
    for blob in blobs:
        walls = _wall_pieces(blob, occupied, whole, whole_size, pad_px)
        if len(walls) < 2:
            out.append(Doorway(blob, None))
            continue
        gaps = [_gap(a, b) for a, b in itertools.pairwise(walls)]
        openings = [(g, mid) for g, mid in gaps if (g - 1.0) * resolution_m >= min_width_m]
        # Openings side by side have wall between them (a wall piece parting two rooms); two
        # crossings of one opening (its jambs broken into pieces) have floor between them.
        if len(openings) >= 2 and not all(_walled_between(occupied, a, b)
                                          for (_, a), (_, b) in itertools.pairwise(openings)):
            openings = []
        if len(openings) < 2:
            # One doorway: between its two widest-apart jambs that leave an opening.
            g = max(gaps, key=lambda x: x[0])[0]
            out.append(Doorway(blob, (g - 1.0) * resolution_m))
            continue
        mids = np.array([mid for _, mid in openings])
        nearest = np.argmin(((blob[:, None, :].astype(float) - mids[None, :, :]) ** 2).sum(axis=2), axis=1)
        out += [Doorway(blob[nearest == k], (g - 1.0) * resolution_m) for k, (g, _) in enumerate(openings)]
    return out


def doorway_clear_width_m(blob: npt.NDArray[np.int64], occupied: npt.NDArray[np.bool_],
                          resolution_m: float, pad_px: int = DOORWAY_JAMB_PAD_PX) -> float | None:
    """The clear width (m) of the labelled doorway ``blob`` ((row, col) pixels) in the map whose
    occupied pixels are ``occupied``: the distance between its jambs, less a pixel (between pixel
    centres). The jambs are the pieces of wall within ``pad_px`` of the blob that belong to the
    largest structures (the walls the doorway is cut in, not furniture or a stray pixel beside
    it). None when fewer than two pieces of wall touch the blob (an opening with no jamb to
    measure from)."""
    return ipa_doorways([blob], occupied, resolution_m, min_width_m=math.inf, pad_px=pad_px)[0].clear_width_m


def door_precision_recall(detected_rc: npt.ArrayLike, blobs: list[npt.NDArray[np.int64]],
                          resolution_m: float,
                          tolerance_m: float = DOOR_MATCH_TOLERANCE_M) -> PrecisionRecall:
    """Match detected door centres ((row, col) pixels, image orientation) to doorway blobs."""
    det = np.asarray(detected_rc, dtype=float).reshape(-1, 2)
    if not blobs:
        raise ValueError("no labelled doorways to score against")
    tol_px = tolerance_m / resolution_m
    pairs: list[tuple[float, int, int]] = []
    for j, blob in enumerate(blobs):
        if det.size == 0:
            break
        d = np.sqrt(((det[:, None, :] - blob[None, :, :].astype(float)) ** 2).sum(axis=2)).min(axis=1)
        for idx in np.flatnonzero(d <= tol_px).tolist():
            pairs.append((float(d[idx]), int(idx), j))
    used_d: set[int] = set()
    used_b: set[int] = set()
    for _, di, bj in sorted(pairs):
        if di in used_d or bj in used_b:
            continue
        used_d.add(di)
        used_b.add(bj)
    tp = len(used_d)
    precision = tp / len(det) if len(det) else 0.0
    return PrecisionRecall(precision, tp / len(blobs), len(det), len(blobs))


__all__ = [
    "DOORWAY_JAMB_PAD_PX",
    "DOORWAY_MIN_CLEAR_M",
    "DOOR_MATCH_TOLERANCE_M",
    "MIN_REGION_PX",
    "Doorway",
    "PrecisionRecall",
    "colour_gt_rooms",
    "door_precision_recall",
    "doorway_clear_width_m",
    "ipa_doorway_blobs",
    "ipa_doorways",
    "ipa_gt_rooms",
    "room_precision_recall",
]
