; The seven-room ERL apartment as the robot knows it before a run: the map (rooms, doors, furniture), the
; devices, the people and objects of the task, and the candidate places from the task's priors (assumed).
; Where things really are is the simulator's business (worlds/erl_home/erl_home.yaml).
; jack is named here for the language and planning examples that mention him; in a simulated run he is the
; door-bell visitor, a stranger the robot has no symbol for until it meets him (visitor_1, ...).
(define (problem erl_home_initial)
  (:domain erl_home)
  (:objects
    entrance_hall hallway living_room dining_room kitchen bedroom bathroom - room
    kitchen_counter kitchen_table kitchen_cabinet bin dining_table coffee_table side_table tv_table
    bookshelf sofa armchair bed bedside_table closet bathroom_drawer plant entrance_shelf - furniture
    glasses mug cup glass coke_can water juice apple lemon candle cardboard_box remote tablet sponge soap
    tissues - item
    annie tracy jack - person
    r2d2 - robot
    bedroom_left_light bedroom_right_light hallway_light - light
    living_room_dimmer - dimmer
    bedroom_blinds - blinds
    door_bell - bell
    doorbell - sound)
  (:init
    (robot_at r2d2 entrance_hall)
    (hand_empty r2d2)
    (connected entrance_hall hallway) (connected hallway entrance_hall)
    (connected hallway living_room) (connected living_room hallway)
    (connected hallway kitchen) (connected kitchen hallway)
    (connected hallway bedroom) (connected bedroom hallway)
    (connected hallway bathroom) (connected bathroom hallway)
    (connected living_room dining_room) (connected dining_room living_room)
    (connected dining_room kitchen) (connected kitchen dining_room)
    (furniture_in kitchen_counter kitchen) (furniture_in kitchen_table kitchen)
    (furniture_in kitchen_cabinet kitchen) (furniture_in bin kitchen)
    (furniture_in dining_table dining_room)
    (furniture_in coffee_table living_room) (furniture_in side_table living_room)
    (furniture_in tv_table living_room) (furniture_in bookshelf living_room)
    (furniture_in sofa living_room) (furniture_in armchair living_room)
    (furniture_in bed bedroom) (furniture_in bedside_table bedroom) (furniture_in closet bedroom)
    (furniture_in bathroom_drawer bathroom)
    (furniture_in plant hallway)
    (furniture_in entrance_shelf entrance_hall)
    (surface kitchen_counter) (surface kitchen_table) (surface kitchen_cabinet)
    (surface dining_table) (surface coffee_table) (surface side_table) (surface tv_table)
    (surface bookshelf) (surface sofa) (surface armchair) (surface bed) (surface bedside_table)
    (surface closet) (surface bathroom_drawer) (surface entrance_shelf)
    (light_off bedroom_left_light) (light_off bedroom_right_light) (light_off hallway_light)
    (device_level living_room_dimmer l0)
    (device_level bedroom_blinds l0)
    (possibly_at annie bedroom) (possibly_at annie living_room)
    (possibly_at glasses bedroom) (possibly_at glasses living_room) (possibly_at glasses kitchen)
    (possibly_at tablet living_room) (possibly_at remote living_room) (possibly_at mug kitchen))
  (:goal (object_at glasses bedroom)))
