"""Occupancy grids: the map model, map_server I/O and ROS array conversion."""

from langnav.maps.errors import MapError
from langnav.maps.grid import (
           FREE,
           OCCUPIED,
           UNKNOWN,
           OccupancyGrid,
           from_ros_data,
           written_resolution,
)
from langnav.maps.io import load_bare_image, load_map, load_map_yaml, save_map

__all__ = ["FREE", "OCCUPIED", "UNKNOWN", "MapError", "OccupancyGrid", "from_ros_data",
           "load_bare_image", "load_map", "load_map_yaml", "save_map", "written_resolution"]
