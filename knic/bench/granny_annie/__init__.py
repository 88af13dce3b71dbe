"""``knic bench granny-annie``: the ERL task benchmark "Catering for Granny Annie's Comfort".

* :mod:`.episodes` (with :mod:`.commands`, :mod:`.placement`, :mod:`.events`): episodes generated from a
  world's data and priors, deterministic per seed;
* :mod:`.baselines`: knic, static closed-world and oracle, applied to an assembled run;
* :mod:`.runner`: one (episode, baseline) per task, serially, in spawned worker processes or on Ray;
* :mod:`.flow`: how an episode starts, the rulebook's task flow for every baseline (Annie calls, the robot
  comes to her room, asks, hears her command, repeats it back; she answers yes only when it means her
  request);
* :mod:`.recording`: the referee's ground-truth timeline and the robot's ERL recording (MCAP bag);
* :mod:`.referee`: the ERL score sheet from ground truth only, and the ranking;
* :mod:`.report`: report.json, report.md and the plots; :mod:`.command`: the command line.
"""
