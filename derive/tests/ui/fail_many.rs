armdyn_derive::robot_model!("tests/ui/fail_many.json");

fn main() {}
