//! The trajectory optimiser (`armdyn::optimal`): minimum-effort and shortest joint moves on
//! the generated derivatives, for the SCARA and the 6- and 7-joint arms.

mod box_qp;
mod free_space_step;
mod moves;
