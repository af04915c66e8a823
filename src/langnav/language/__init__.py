"""Prompt -> intent: the intent schema, the translator seam, the offline parser and LLM backends."""

from langnav.language.errors import LLMError, TranslationError
from langnav.language.intent import Intent, Step
from langnav.language.translator import Context, Translator, clean_prompt, get_translator

__all__ = ["Context", "Intent", "LLMError", "Step", "TranslationError", "Translator", "clean_prompt",
           "get_translator"]
