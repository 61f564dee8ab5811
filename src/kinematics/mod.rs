//! Inverse kinematics for any arm, behind one interface.
