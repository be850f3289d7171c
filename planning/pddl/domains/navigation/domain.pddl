; Navigation on the courtyard: the robot drives between places joined by connections; a known
; obstacle blocks a connection (both directions are listed). The robot inspects checkpoints
; on its way. The planner service adds (blocked a b) when the laser finds an obstacle the problem did
; not know (IS_OBSTACLE_KNOWN) and plans again from where the robot stands (RE-PLAN). Only
; checkpoints can be inspected (else every place would be a pointless branch of the search).
(define (domain navigation)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types place robot)
  (:predicates (at ?r - robot ?p - place)
               (connected ?a ?b - place)
               (blocked ?a ?b - place)
               (checkpoint ?p - place)
               (inspected ?p - place))
  (:action drive
    :parameters (?r - robot ?from ?to - place)
    :precondition (and (at ?r ?from) (connected ?from ?to) (not (blocked ?from ?to)) (not (= ?from ?to)))
    :effect (and (not (at ?r ?from)) (at ?r ?to)))
  (:action inspect
    :parameters (?r - robot ?p - place)
    :precondition (and (at ?r ?p) (checkpoint ?p) (not (inspected ?p)))
    :effect (inspected ?p)))
