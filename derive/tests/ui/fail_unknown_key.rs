armdyn_derive::robot_model!("tests/ui/fail_unknown_key.json");

fn main() {}
