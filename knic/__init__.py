"""KnIC, the Knowledge Inference Component.

Turns sensor data into symbolic PDDL knowledge (KGM-1 providers, KGM-2 cognition, KGM-3 KP' components), keeps
the knowledge base true while the world changes, and hosts the command line. Importing this package is cheap:
subpackages are imported by their users.
"""

__version__ = "0.1.0"
