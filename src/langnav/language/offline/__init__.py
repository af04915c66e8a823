"""The ``offline`` translator: prompt -> :class:`~langnav.language.intent.Intent` with no network
and no model, from tables of words (``lexicon``), number reading (``numbers``), step splitting
(``splitter``) and clause reading (``parser``).

``Intent.confidence`` is the lowest confidence of its steps: below :data:`CONFIDENT` a reading has
words left unread, a guessed default or a borrowed verb, and an ``auto`` translator should ask an
LLM. Refusals (unsafe requests, names the map cannot know, things the robot cannot do) are
confident: they come with a ``clarification`` and no steps.
"""

from __future__ import annotations

from langnav.language.offline.translator import CONFIDENT, OfflineTranslator, translate_offline
from langnav.language.translator import register

register("offline", OfflineTranslator)

__all__ = ["CONFIDENT", "OfflineTranslator", "translate_offline"]
