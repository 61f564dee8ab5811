armdyn_derive::robot_model!("tests/ui/fail_syntax.json");

fn main() {}
