from langnav.errors import LangnavError


class AnalysisError(LangnavError):
    """Map analysis failed on a grid that loaded (for example: no free space at all)."""
