"""The project's exception tree.

Every error a user can cause derives from :class:`KnicError`. Its message is one line that names what is wrong
and where (file, line, symbol). The command line prints it as ``knic: error: <message>`` and exits with the
error's ``exit_code``.
"""


class KnicError(Exception):
    """Root of every error KnIC raises on purpose."""

    exit_code = 2


class PDDLError(KnicError):
    """A PDDL domain or problem is malformed or inconsistent."""


class PDDLParseError(PDDLError):
    """A PDDL file does not parse; the message names file, line and what was expected."""


class PDDLValidationError(PDDLError):
    """A PDDL file parses but is inconsistent (unknown predicate, wrong type, problem for another domain)."""


class KnowledgeBaseError(KnicError):
    """A knowledge-base write was refused; the knowledge base is unchanged."""


class JournalError(KnowledgeBaseError):
    """The history journal cannot be opened or read."""


class PlanningError(KnicError):
    """No engine can take the problem, or planning failed for a reason other than unsolvability."""


class WorldError(KnicError):
    """A world or scenario file is invalid, or the simulator was asked something impossible."""


class ActionError(KnicError):
    """An action implementation is missing or misconfigured."""


class InferenceError(KnicError):
    """A knowledge unit, a role file or the inference pipeline's configuration is invalid; nothing changed."""


class LanguageError(KnicError):
    """A text or spoken command was not understood; nothing was added."""

    exit_code = 4


class AudioError(KnicError):
    """An audio file cannot be read or converted."""
