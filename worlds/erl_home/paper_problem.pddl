; The paper's trace (seed 004, section IV.B) without its false seed fact:
; where the glasses are is unknown, so every room is a candidate (assumed).
(define (problem erl_paper_glasses)
  (:domain erl_home)
  (:objects
    kitchen bedroom entrance living_room - room
    bed kitchen_table entrance_shelf sofa - furniture
    glasses - item
    r2d2 - robot
    annie - person)
  (:init
    (robot_at r2d2 bedroom)
    (hand_empty r2d2)
    (person_at annie bedroom)
    (connected bedroom kitchen) (connected kitchen bedroom)
    (connected kitchen entrance) (connected entrance kitchen)
    (connected entrance living_room) (connected living_room entrance)
    (connected living_room bedroom) (connected bedroom living_room)
    (furniture_in bed bedroom)
    (furniture_in kitchen_table kitchen)
    (furniture_in entrance_shelf entrance)
    (furniture_in sofa living_room)
    (surface bed) (surface kitchen_table) (surface entrance_shelf) (surface sofa)
    (possibly_at glasses kitchen)
    (possibly_at glasses entrance)
    (possibly_at glasses living_room))
  (:goal (object_at glasses bedroom)))
