"""Map understanding: the elements people refer to (rooms, doors, walls, corners, ...)."""

from langnav.analysis.elements import (
    Corner,
    Door,
    Element,
    ElementKind,
    MapAnalysis,
    NarrowPassage,
    Obstacle,
    Room,
    UnexploredArea,
    Wall,
    reference_point,
)
from langnav.analysis.errors import AnalysisError
from langnav.analysis.params import DEFAULT_PARAMS, AnalysisParams
from langnav.analysis.pipeline import AnalysisCache, analyze

__all__ = ["DEFAULT_PARAMS", "AnalysisCache", "AnalysisError", "AnalysisParams", "Corner", "Door", "Element",
           "ElementKind", "MapAnalysis", "NarrowPassage", "Obstacle", "Room", "UnexploredArea",
           "Wall", "analyze", "reference_point"]
