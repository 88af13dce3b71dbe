"""KGM-2: the cognitive model layer, turning LLKUs into CKUs with spatial abstraction and the robot's role.

* :mod:`knic.kgm2.tracking` -- association over time with a radius and a miss counter (seed 002).
* :mod:`knic.kgm2.roles` -- roles as data (``knic/roles.yaml``): rates and priorities per class and room.
* :mod:`knic.kgm2.cognition` -- the component that runs all of it and publishes CKUs (entities, places).
* :mod:`knic.kgm2.attention` -- the role's revisits: which room to look at next when idle.

Geometry (voxel keys, volumes, entity octomaps) is the spatial floor's, :mod:`knic.spatial`.
"""
