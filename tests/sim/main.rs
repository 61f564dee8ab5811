//! Tests of `armdyn::sim`: the torque history reader, joint friction and the end stops. A file
//! here tests the file of the same name in `src/sim/`; the step schedule, the plant's steps
//! and the sensor faults are tested in their own files, through private items.

mod end_stops;
mod friction;
mod torque_history;
