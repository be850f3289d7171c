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
;;problem
; A 3 x 3 courtyard (pXY: column X, row Y); obstacles block two ways into the centre.
(define (problem courtyard-3x3)
  (:domain navigation)
  (:objects robot1 - robot p11 p21 p31 p12 p22 p32 p13 p23 p33 - place)
  (:init (at robot1 p11)
         (connected p11 p21) (connected p21 p11) (connected p11 p12) (connected p12 p11) (connected p21 p31) (connected p31 p21)
         (connected p21 p22) (connected p22 p21) (connected p31 p32) (connected p32 p31) (connected p12 p22) (connected p22 p12)
         (connected p12 p13) (connected p13 p12) (connected p22 p32) (connected p32 p22) (connected p22 p23) (connected p23 p22)
         (connected p32 p33) (connected p33 p32) (connected p13 p23) (connected p23 p13) (connected p23 p33) (connected p33 p23)
         (blocked p21 p22) (blocked p22 p21) (blocked p12 p22) (blocked p22 p12))
  (:goal (and (at robot1 p33))))
