from langnav.errors import LangnavError


class RobotError(LangnavError):
    """A robot backend failed: not connected, connection lost, timed out, malformed message."""


class RobotTimeout(RobotError):
    """A wait on the robot ran out of time."""
