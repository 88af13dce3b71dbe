"""The web view: the robot's mind, live in a browser (an adapter at the edge, like ROS 2).

``knic serve --journal FILE`` follows a run's journal (live or finished); ``knic run --serve`` serves the same
page from inside a run, with the components, the bus, KGM-2's octomaps, the ground truth and a goal box.

Modules, from the data to the wire:

* :mod:`knic.web.scene` -- the floor plan and where things are believed to be, from a knowledge-base state;
* :mod:`knic.web.view` -- queries over a journal file followed read-only, and the trace file;
* :mod:`knic.web.live` -- the running system's side: a scheduler component that takes goals into the intake
  and publishes snapshots for the server thread;
* :mod:`knic.web.audio` -- spoken goals uploaded as WAV, decoded in memory;
* :mod:`knic.web.hub` -- the server's polling loop and server-sent events;
* :mod:`knic.web.app` -- the FastAPI application (page, JSON API, OpenAPI at ``/docs``);
* :mod:`knic.web.limits` -- request body limits;
* :mod:`knic.web.server` -- uvicorn on its own thread, loopback unless a token guards it.

Only this package imports the web framework (the optional extra ``web``); importing ``knic.web`` itself
imports none of it, and nothing outside ``knic.web`` and ``knic.cli`` imports ``knic.web``.
"""
