; One package across town.
(define (problem logistics-1)
  (:domain logistics)
  (:objects c1 - city depot1 - location air1 - airport t1 - truck p1 - package)
  (:init (in-city depot1 c1) (in-city air1 c1) (at t1 depot1) (at p1 depot1))
  (:goal (at p1 air1)))
