; Three cities, four packages going different ways.
(define (problem logistics-3)
  (:domain logistics)
  (:objects c1 c2 c3 - city depot1 depot2 depot3 - location air1 air2 air3 - airport
            t1 t2 t3 - truck plane - airplane p1 p2 p3 p4 - package)
  (:init (in-city depot1 c1) (in-city air1 c1) (in-city depot2 c2) (in-city air2 c2)
         (in-city depot3 c3) (in-city air3 c3)
         (at t1 depot1) (at t2 depot2) (at t3 air3) (at plane air1)
         (at p1 depot1) (at p2 depot2) (at p3 air3) (at p4 depot1))
  (:goal (and (at p1 depot3) (at p2 air1) (at p3 depot2) (at p4 air2))))
