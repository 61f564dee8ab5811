armdyn_derive::robot_model!("tests/ui/does_not_exist.json");

fn main() {}
