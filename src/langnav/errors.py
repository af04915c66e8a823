"""The root of langnav's exception tree.

LangnavError
├── maps.errors.MapError            a map file or array that cannot be read or is malformed
├── analysis.errors.AnalysisError   map analysis failed on an otherwise valid grid
├── language.errors.TranslationError  a prompt could not be turned into an intent
│   └── language.errors.LLMError      an LLM backend failed (network, timeout, bad answer)
├── grounding.errors.GroundingError an intent names something the map does not have
├── plan.errors.PlanRejected        the validator refused a plan (reasons attached)
└── robot.errors.RobotError         a robot backend failed (connection lost, timeout)

Only the CLI and the web layer turn these into exit codes or HTTP responses.
"""


class LangnavError(Exception):
    """Base class of every error langnav raises on purpose."""
