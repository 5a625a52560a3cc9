"""Built-in systems, loaded by name; model files (TOML) by path."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from hydroservo.errors import ModelFileError
from hydroservo.models.flight_simulator import flight_simulator
from hydroservo.models.servo_solenoid import servo_solenoid_cylinder
from hydroservo.system import System

__all__ = ["BUILTIN", "available_models", "load_model"]

#: name -> (builder, one-line description, validation status)
BUILTIN: dict[str, tuple[Callable[[], System], str, str]] = {
    "flight-simulator": (
        flight_simulator,
        "Seed 003: closed-loop flight-simulator actuator with MOOG 72 two-stage servovalve",
        "steady state and frequencies reproduced, transient figures not (docs/validation.md)",
    ),
    "servo-solenoid-cylinder": (
        servo_solenoid_cylinder,
        "Seed 000: Vickers KBSDG4V-3 servo-solenoid valve positioning a cylinder and 50 kg mass",
        "valve reproduces the published datasheet fit and Bode parameters; circuit is an example (no published data)",
    ),
}


def available_models() -> dict[str, str]:
    """Names and descriptions of the built-in systems."""
    return {name: desc for name, (_, desc, _) in BUILTIN.items()}


def load_model(name_or_path: str | Path) -> System:
    """A built-in system by name, or a system from a TOML model file."""
    key = str(name_or_path)
    if key in BUILTIN:
        return BUILTIN[key][0]()
    path = Path(key)
    if path.suffix.lower() == ".toml" or path.exists():
        from hydroservo.modelfile import read_model

        return read_model(path)
    raise ModelFileError(f"{key!r} is neither a built-in model ({', '.join(BUILTIN)}) nor a model file (.toml)")
