"""Collects errors and warnings with the EDS line they refer to."""

from dataclasses import dataclass


@dataclass(frozen=True)
class Diagnostic:
    severity: str  # 'error' or 'warning'
    line: int
    message: str


class Diagnostics:
    def __init__(self) -> None:
        self._items = []

    def error(self, line: int, message: str) -> None:
        self._items.append(Diagnostic("error", line, message))

    def warning(self, line: int, message: str) -> None:
        self._items.append(Diagnostic("warning", line, message))

    @property
    def items(self) -> list:
        """All diagnostics ordered by line; the order of reporting breaks ties."""
        return sorted(self._items, key=lambda d: d.line)

    @property
    def errors(self) -> list:
        return [d for d in self.items if d.severity == "error"]

    @property
    def warnings(self) -> list:
        return [d for d in self.items if d.severity == "warning"]

    @property
    def error_count(self) -> int:
        return sum(1 for d in self._items if d.severity == "error")

    @property
    def has_errors(self) -> bool:
        return any(d.severity == "error" for d in self._items)

    def format(self, filename: str) -> list:
        return [f"{filename}:{d.line}: {d.severity}: {d.message}" for d in self.items]
