"""Errors of the named-place store."""

from langnav.errors import LangnavError


class PlaceError(LangnavError):
    """A named place cannot be stored, found or read (bad name, unknown name, unreadable file)."""


class UnknownPlace(PlaceError):
    """No place has that name; the message lists the names that exist."""


class BadPlaceName(PlaceError):
    """A name that cannot be a place's name (empty, too long, control characters, a map label)."""
