; blocksworld with a precondition missing its parentheses (line 4, column 5)
(define (domain blocksworld) (:requirements :strips)
  (:predicates (clear ?x)) (:action a :parameters (?x) :precondition
    clear ?x))
