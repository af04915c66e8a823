from langnav.errors import LangnavError


class GroundingError(LangnavError):
    """The intent names something the map does not have ("the third door" where there are two)."""
