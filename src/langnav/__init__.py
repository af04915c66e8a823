"""langnav: drive a ROS 2 mobile robot in plain language, grounded in its map.

Public API is re-exported here; see the subpackages for each domain:

- :mod:`langnav.maps`       occupancy grids in and out (map_server YAML, images, ROS arrays)
- :mod:`langnav.analysis`   the elements people talk about (rooms, doors, walls, ...)
- :mod:`langnav.language`   prompt -> intent (offline parser, LLM translators)
- :mod:`langnav.grounding`  intent + map + pose -> robot commands
- :mod:`langnav.plan`       the command union, validator and executor
- :mod:`langnav.robot`      robot backends (simulator, rosbridge, rclpy)
- :mod:`langnav.web`        the chat + live map web app
- :mod:`langnav.eval`       the paper's metrics
"""

from langnav.errors import LangnavError

__all__ = ["LangnavError"]
__version__ = "0.1.0"
