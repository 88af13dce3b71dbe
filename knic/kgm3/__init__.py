"""KGM-3: the KP' components, turning CKU streams into PDDL facts asserted and retracted in the KB.

* :mod:`knic.kgm3.base` -- the KP' base class (with the places it learns from the location CKUs) and the
  hysteresis (:class:`~knic.kgm3.base.Confirmer`).
* :mod:`knic.kgm3.places` -- robot_at, object_at / object_on, found (and the place logic people share).
* :mod:`knic.kgm3.people` -- person_at aged in time, visitors met as new instances.
* :mod:`knic.kgm3.relations` -- person_near, sound_at, light_on / light_off, device_level.
* :mod:`knic.kgm3.search` -- explored (with a time to live) and the possibly_at search candidates.
* :mod:`knic.kgm3.sightings` -- the perception the actions steer by, fed from the entity CKUs.
"""
