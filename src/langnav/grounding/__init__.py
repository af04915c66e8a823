"""Intent + map analysis + robot pose -> robot commands whose coordinates code computed."""

from langnav.grounding.errors import GroundingError
from langnav.grounding.geometry import FreeSpace, Pose, free_space_for
from langnav.grounding.ground import GroundedPlan, GroundedStep, as_pose, ground
from langnav.grounding.history import HistoryView, PoseHistory

__all__ = ["FreeSpace", "GroundedPlan", "GroundedStep", "GroundingError", "HistoryView", "Pose", "PoseHistory", "as_pose",
           "free_space_for", "ground"]
