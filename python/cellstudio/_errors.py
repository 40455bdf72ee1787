"""The package's one exception class, raised by the Rust side with the command line's text."""

from ._native import CellstudioError

__all__ = ["CellstudioError"]
