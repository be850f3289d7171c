; Six blocks in two towers, rebuilt into one.
(define (problem towers-6)
  (:domain blocksworld)
  (:objects a b c d e f - block)
  (:init (clear a) (on a b) (on b c) (ontable c) (clear d) (on d e) (on e f) (ontable f) (handempty))
  (:goal (and (on f e) (on e d) (on d c) (on c b) (on b a))))
