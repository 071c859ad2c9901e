// HOSTILE FIXTURE defines_other_stage (attack class 6: defines another stage's functions).
// Stage 01's file also defines every function of stage 04 (today's stub of stage 04, pulled in by //@stub 04, so each signature is the one stage 04's header declares today), to break stage 04's build (duplicate symbols) or replace the student's stage-04 code.
// The hardened grader must give this file 0 points on stage 01 and leave stage 04's points unchanged.
//@tail

// ATTACK: stage 04's functions, defined in stage 01's file. When stage 04 is graded with the
// submission's stage 01 (--reference none) they collide with the student's stage-04 code.
//@stub 04
