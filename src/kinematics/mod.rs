//! SCARA kinematics beyond the generated forward model: closed-form inverse kinematics with
//! elbow choice, joint-space references from Cartesian ones, and workspace classification
//! of a whole reference before a run (thesis Sections 3.1.4, 3.1.5 and 4.4).
