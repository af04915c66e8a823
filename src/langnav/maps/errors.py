from langnav.errors import LangnavError


class MapError(LangnavError):
    """A map file or array that cannot be used. The message names the file and the problem."""
