armdyn_derive::robot_model!("tests/ui/fail_format.json");

fn main() {}
