; One package to another city by truck, airplane and truck.
(define (problem logistics-2)
  (:domain logistics)
  (:objects c1 c2 - city depot1 depot2 - location air1 air2 - airport t1 t2 - truck plane - airplane p1 - package)
  (:init (in-city depot1 c1) (in-city air1 c1) (in-city depot2 c2) (in-city air2 c2)
         (at t1 depot1) (at t2 air2) (at plane air1) (at p1 depot1))
  (:goal (at p1 depot2)))
