from langnav.errors import LangnavError


class TranslationError(LangnavError):
    """A prompt could not be turned into an intent (empty, too long, unreadable)."""


class LLMError(TranslationError):
    """An LLM backend failed: not configured, unreachable, timed out, or answered off-schema twice."""
