"""The bottom layer every other package stands on: nothing here imports another KnIC package.

* :mod:`core.errors` -- the project's exception tree (one root, :class:`~core.errors.KnicError`).
"""
