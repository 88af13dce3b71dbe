"""Acoustic models for the recogniser: the pocketsphinx wheel's US English model, optionally adapted.

The wheel's model was trained on human American English. The speakers of the simulated apartment are espeak-ng
voices, which it recognises poorly: on the shipped test set frame-with-arguments accuracy is 0.77 with it and
about 0.5 on voices the decoder settings were not tuned on. :data:`MODEL_DIR` holds a MAP adaptation of the
same model to espeak-ng speech (means, variances and mixture weights; the phone set, state tying and
transition matrices are the wheel's), built by :mod:`knic.language.acoustic.build` from sentences sampled from
the command grammar and spoken in espeak-ng voices that are in neither the test set nor the development set.
With it the recogniser reaches about 0.93 on the test set and 0.90 on the development set (``knic bench
speech``). For human speakers use ``"base"``, or build an adaptation from recordings of the robot's users with
``build --corpus``.
"""

from __future__ import annotations

from pathlib import Path

from core.errors import LanguageError

#: The espeak-ng adaptation (``means``, ``variances``, ``sendump``, ``manifest.json``) built by :mod:`.build`
#: from 480 sentences in 16 voices: the grammar decoder and the answer recogniser use it.
MODEL_DIR = Path(__file__).resolve().parent / "espeak"
#: The sub-folder of an adaptation that the n-gram decoder uses instead when it is there. ``espeak/ngram``:
#: the adaptation built from 3000 sentences in 214 voices (``build --sentences 3000``), which raised the
#: n-gram decoder's dev frame+args from 0.825 to 0.871 but broke the grammar decoder with its settings (most
#: commands refused: speech_dev frame+args 0.89 -> 0.38) and the answer recogniser ("no" heard as "uh no uh
#: huh"), so those keep the first adaptation.
NGRAM_SUBFOLDER = "ngram"
#: Named acoustic models: a folder of adapted files, or None for the wheel's model unchanged.
ACOUSTIC_MODELS: dict[str, Path | None] = {"espeak": MODEL_DIR, "base": None}
#: The model the grammar decoder and the answer recogniser load unless told otherwise.
DEFAULT_ACOUSTIC_MODEL = "espeak"
#: Named sets of acoustic models for the n-gram decoder: it decodes each utterance with every member and
#: keeps the one that fits the audio best (:func:`knic.language.membership.choose_member`). ``auto``: the
#: espeak-ng adaptation, which hears espeak-ng voices far better, and the wheel's model trained on human
#: speech, which hears other speakers far better (the adaptation collapses on other engines' voices: dev
#: frame+args 0.07 against the wheel's 0.86).
ENSEMBLES: dict[str, tuple[str, ...]] = {"auto": ("espeak", "base")}
#: The acoustic model (or set) the n-gram decoder loads unless told otherwise.
DEFAULT_NGRAM_ACOUSTIC_MODEL = "auto"
#: The files of an adaptation and the pocketsphinx options that load them.
ADAPTED_FILES = {"means": "mean", "variances": "var", "sendump": "sendump"}


def wheel_model_dir() -> Path:
    """The pocketsphinx wheel's model folder (``en-us/`` acoustic model and ``cmudict-en-us.dict``)."""
    import pocketsphinx

    return Path(pocketsphinx.__file__).resolve().parent / "model" / "en-us"


def acoustic_model_for(decoder: str, model: str | Path | None = None) -> str | Path:
    """``model``, or when None the default of ``decoder``: :data:`DEFAULT_NGRAM_ACOUSTIC_MODEL` for
    ``"ngram"``, :data:`DEFAULT_ACOUSTIC_MODEL` for the grammar decoder and the answer recogniser."""
    if model is not None:
        return model
    return DEFAULT_NGRAM_ACOUSTIC_MODEL if decoder == "ngram" else DEFAULT_ACOUSTIC_MODEL


def ensemble_members(model: str | Path) -> tuple[str | Path, ...]:
    """The acoustic models a name of :data:`ENSEMBLES` stands for, or the model itself alone."""
    if isinstance(model, str) and model in ENSEMBLES:
        return ENSEMBLES[model]
    return (model,)


def acoustic_model_options(model: str | Path, *, decoder: str = "grammar") -> dict[str, object]:
    """pocketsphinx options that load an acoustic model: a name of :data:`ACOUSTIC_MODELS` or a folder; for
    ``decoder="ngram"`` its :data:`NGRAM_SUBFOLDER` when that holds an adaptation.

    Raises:
        LanguageError: the name is unknown, or the folder lacks one of the adapted files.
    """
    if isinstance(model, str) and model in ENSEMBLES:
        members = " and ".join(ENSEMBLES[model])
        raise LanguageError(f"acoustic model {model!r} is {members}: only the n-gram decoder takes it")
    if isinstance(model, str) and model in ACOUSTIC_MODELS:
        folder = ACOUSTIC_MODELS[model]
    elif isinstance(model, Path) or "/" in str(model) or Path(str(model)).is_dir():
        folder = Path(model)
    else:
        names = ", ".join(sorted([*ACOUSTIC_MODELS, *ENSEMBLES]))
        raise LanguageError(f"unknown acoustic model {model!r}: expected one of {names} or a folder")
    if folder is None:
        return {}
    if decoder == "ngram" and all((folder / NGRAM_SUBFOLDER / name).is_file() for name in ADAPTED_FILES):
        folder = folder / NGRAM_SUBFOLDER
    missing = [name for name in ADAPTED_FILES if not (folder / name).is_file()]
    if missing:
        raise LanguageError(f"acoustic model folder {folder}: missing {', '.join(missing)}")
    return {option: str(folder / name) for name, option in ADAPTED_FILES.items()}
