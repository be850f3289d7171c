; Take the book to the office, leave the pen at home.
(define (problem briefcase-1)
  (:domain briefcase)
  (:objects home office - location)
  (:init (is-at home) (at book home) (at pen home))
  (:goal (and (at book office) (at pen home) (not (in book)) (is-at home))))
