; The ERL apartment domain ("Catering for Granny Annie's Comfort").
;
; Unknown object and person locations are modelled without false facts: a
; candidate place is the assumed fact (possibly_at ?e ?l), written by KnIC with
; belief status "assumed", and search_object / search_person are sensing
; actions whose effects only count once perception confirms them.
; (surface ?f): items can be put on furniture ?f (static, from the world data;
; a bin or a plant carries nothing).
;
; (explored ?l) is perception's: the camera has covered room ?l lately.
; (searched ?e ?l) is the search's own record: the robot looked for ?e in ?l,
; so a room searched for the tablet can still be searched for Annie, and a
; search over every candidate room ends. (possibly_on ?o ?f) is the assumed
; candidate furniture of an item asked for "from" that furniture; the sensing
; action search_furniture looks there and pick_from takes it from there,
; making (taken_from ?o ?f) true, the goal that keeps the request's source.
; (to_accompany ?p): someone asked for ?p to be taken somewhere (a person_at
; goal); only then does the robot meet and guide ?p, never to bring a person
; to where an item is.
(define (domain erl_home)
  (:requirements :strips :typing :negative-preconditions)
  ; light_on / light_off are kept complementary by the actions and by the device KP'.
  (:types
    room furniture level sound device entity - object
    robot person item - entity
    light dimmer blinds bell - device
  )
  (:constants l0 l25 l50 l75 l100 - level)
  (:predicates
    (robot_at ?r - robot ?l - room)
    (person_at ?p - person ?l - room)
    (object_at ?o - item ?l - room)
    (object_on ?o - item ?f - furniture)
    (furniture_in ?f - furniture ?l - room)
    (surface ?f - furniture)
    (connected ?a - room ?b - room)
    (possibly_at ?e - entity ?l - room)
    (found ?e - entity)
    (explored ?l - room)
    (searched ?e - entity ?l - room)
    (possibly_on ?o - item ?f - furniture)
    (taken_from ?o - item ?f - furniture)
    (to_accompany ?p - person)
    (reported ?e - entity)
    (holding ?r - robot ?o - item)
    (hand_empty ?r - robot)
    (has ?p - person ?o - item)
    (escorting ?r - robot ?p - person)
    (person_near ?p - person ?q - person)
    (sound_at ?s - sound ?l - room)
    (light_on ?d - light)
    (light_off ?d - light)
    (device_level ?d - device ?v - level)
  )

  (:action move
    :parameters (?r - robot ?from - room ?to - room)
    :precondition (and (robot_at ?r ?from) (connected ?from ?to))
    :effect (and (robot_at ?r ?to) (not (robot_at ?r ?from))))

  (:action search_object
    :parameters (?r - robot ?o - item ?l - room)
    :precondition (and (robot_at ?r ?l) (possibly_at ?o ?l) (not (found ?o)) (not (searched ?o ?l)))
    :effect (and (found ?o) (object_at ?o ?l) (searched ?o ?l)))

  (:action search_furniture
    :parameters (?r - robot ?o - item ?f - furniture ?l - room)
    :precondition (and (robot_at ?r ?l) (furniture_in ?f ?l) (possibly_on ?o ?f) (not (found ?o))
                       (not (searched ?o ?l)))
    :effect (and (found ?o) (object_at ?o ?l) (object_on ?o ?f) (searched ?o ?l)))

  (:action search_person
    :parameters (?r - robot ?p - person ?l - room)
    :precondition (and (robot_at ?r ?l) (possibly_at ?p ?l) (not (found ?p)) (not (searched ?p ?l)))
    :effect (and (found ?p) (person_at ?p ?l) (searched ?p ?l)))

  (:action pick
    :parameters (?r - robot ?o - item ?l - room)
    :precondition (and (robot_at ?r ?l) (object_at ?o ?l) (hand_empty ?r))
    :effect (and (holding ?r ?o) (not (hand_empty ?r)) (not (object_at ?o ?l))))

  (:action pick_from
    :parameters (?r - robot ?o - item ?f - furniture ?l - room)
    :precondition (and (robot_at ?r ?l) (object_at ?o ?l) (object_on ?o ?f) (furniture_in ?f ?l)
                       (hand_empty ?r))
    :effect (and (holding ?r ?o) (not (hand_empty ?r)) (not (object_at ?o ?l)) (not (object_on ?o ?f))
                 (taken_from ?o ?f)))

  (:action place
    :parameters (?r - robot ?o - item ?f - furniture ?l - room)
    :precondition (and (robot_at ?r ?l) (holding ?r ?o) (furniture_in ?f ?l) (surface ?f))
    :effect (and (object_at ?o ?l) (object_on ?o ?f) (hand_empty ?r) (not (holding ?r ?o))))

  (:action give
    :parameters (?r - robot ?o - item ?p - person ?l - room)
    :precondition (and (robot_at ?r ?l) (person_at ?p ?l) (holding ?r ?o))
    :effect (and (has ?p ?o) (hand_empty ?r) (not (holding ?r ?o))))

  (:action meet
    :parameters (?r - robot ?p - person ?l - room)
    :precondition (and (robot_at ?r ?l) (person_at ?p ?l) (to_accompany ?p))
    :effect (escorting ?r ?p))

  (:action guide
    :parameters (?r - robot ?p - person ?from - room ?to - room)
    :precondition (and (robot_at ?r ?from) (person_at ?p ?from) (escorting ?r ?p)
                       (connected ?from ?to))
    :effect (and (robot_at ?r ?to) (person_at ?p ?to)
                 (not (robot_at ?r ?from)) (not (person_at ?p ?from))))

  (:action report
    :parameters (?r - robot ?e - entity)
    :precondition (found ?e)
    :effect (reported ?e))

  (:action switch_on
    :parameters (?r - robot ?d - light)
    :precondition (light_off ?d)
    :effect (and (light_on ?d) (not (light_off ?d))))

  (:action switch_off
    :parameters (?r - robot ?d - light)
    :precondition (light_on ?d)
    :effect (and (light_off ?d) (not (light_on ?d))))

  (:action set_level
    :parameters (?r - robot ?d - device ?from - level ?to - level)
    :precondition (device_level ?d ?from)
    :effect (and (device_level ?d ?to) (not (device_level ?d ?from))))
)
