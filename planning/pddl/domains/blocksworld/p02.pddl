; Four blocks: reverse the tower d-c-b-a.
(define (problem reverse-4)
  (:domain blocksworld)
  (:objects a b c d - block)
  (:init (clear a) (on a b) (on b c) (on c d) (ontable d) (handempty))
  (:goal (and (on d c) (on c b) (on b a))))
