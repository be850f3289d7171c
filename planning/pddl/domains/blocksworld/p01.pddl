; Sussman's anomaly: C on A, B on the table; build A on B on C.
(define (problem sussman)
  (:domain blocksworld)
  (:objects a b c - block)
  (:init (clear c) (clear b) (ontable a) (ontable b) (on c a) (handempty))
  (:goal (and (on a b) (on b c))))
