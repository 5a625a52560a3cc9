"""The version of hydroservo (the one place it is written, besides pyproject.toml)."""

__version__ = "0.8.0"
