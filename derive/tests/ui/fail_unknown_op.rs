armdyn_derive::robot_model!("tests/ui/fail_unknown_op.json");

fn main() {}
