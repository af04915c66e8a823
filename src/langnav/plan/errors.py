from langnav.errors import LangnavError


class PlanRejected(LangnavError):
    """The validator refused a plan. ``reasons`` are sentences a user can read."""

    def __init__(self, reasons: list[str]) -> None:
        self.reasons = list(reasons)
        super().__init__("; ".join(self.reasons) if self.reasons else "plan rejected")
