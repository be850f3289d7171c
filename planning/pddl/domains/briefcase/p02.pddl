; Book to the office, pen to the library, the briefcase back home and empty.
(define (problem briefcase-2)
  (:domain briefcase)
  (:objects home office library - location)
  (:init (is-at home) (at book home) (at pen home))
  (:goal (and (at book office) (at pen library) (not (in book)) (not (in pen)) (is-at home))))
