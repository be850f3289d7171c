; Briefcase (Pednault's): moving the briefcase moves everything in it (conditional effects).
(define (domain briefcase)
  (:requirements :strips :typing :negative-preconditions :conditional-effects)
  (:types location portable)
  (:constants book pen - portable)
  (:predicates (at ?o - portable ?l - location) (in ?o - portable) (is-at ?l - location))
  (:action move
    :parameters (?from ?to - location)
    :precondition (and (is-at ?from) (not (is-at ?to)))
    :effect (and (is-at ?to) (not (is-at ?from))
                 (when (in book) (and (at book ?to) (not (at book ?from))))
                 (when (in pen) (and (at pen ?to) (not (at pen ?from))))))
  (:action put-in
    :parameters (?o - portable ?l - location)
    :precondition (and (at ?o ?l) (is-at ?l) (not (in ?o)))
    :effect (in ?o))
  (:action take-out
    :parameters (?o - portable)
    :precondition (in ?o)
    :effect (not (in ?o))))
;;problem
; Take the book to the office, leave the pen at home.
(define (problem briefcase-1)
  (:domain briefcase)
  (:objects home office - location)
  (:init (is-at home) (at book home) (at pen home))
  (:goal (and (at book office) (at pen home) (not (in book)) (is-at home))))
