; Gripper with 1 ball(s) to carry from room A to room B.
(define (problem gripper-1)
  (:domain gripper)
  (:objects rooma roomb - room left right - gripper ball1 - ball)
  (:init (at-robby rooma) (free left) (free right) (at ball1 rooma))
  (:goal (and (at ball1 roomb))))
