"""KGM-1: the knowledge providers (KP), one per sensor, turning readings into LLKUs on the bus.

* :mod:`knic.kgm1.sources` -- typed protocols of the sensors consumed, the shared camera, the frame view.
* :mod:`knic.kgm1.camera` -- objects and people from the RGB-D camera.
* :mod:`knic.kgm1.providers` -- robot pose, sound events, device readings.
* :mod:`knic.kgm1.locations` -- the 2D map as places: one octomap per room, furniture and its support volume.
"""
