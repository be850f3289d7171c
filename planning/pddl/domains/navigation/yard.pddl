; The PDDL yard (sim_hal/worlds/pddl_yard.world, firmware/config/pddl_yard.toml): 4 x 3 places,
; 4-connected; two walls the problem knows block (p21 p22) and (p32 p42). The crates between p31
; and p41 are not in it: the robot finds them and the service adds (blocked p31 p41).
(define (problem pddl-yard)
  (:domain navigation)
  (:objects robot1 - robot p11 p21 p31 p41 p12 p22 p32 p42 p13 p23 p33 p43 - place)
  (:init (at robot1 p11)
         (connected p11 p21) (connected p21 p11) (connected p21 p31) (connected p31 p21) (connected p31 p41) (connected p41 p31)
         (connected p12 p22) (connected p22 p12) (connected p22 p32) (connected p32 p22) (connected p32 p42) (connected p42 p32)
         (connected p13 p23) (connected p23 p13) (connected p23 p33) (connected p33 p23) (connected p33 p43) (connected p43 p33)
         (connected p11 p12) (connected p12 p11) (connected p12 p13) (connected p13 p12)
         (connected p21 p22) (connected p22 p21) (connected p22 p23) (connected p23 p22)
         (connected p31 p32) (connected p32 p31) (connected p32 p33) (connected p33 p32)
         (connected p41 p42) (connected p42 p41) (connected p42 p43) (connected p43 p42)
         (blocked p21 p22) (blocked p22 p21) (blocked p32 p42) (blocked p42 p32))
  (:goal (at robot1 p41)))
