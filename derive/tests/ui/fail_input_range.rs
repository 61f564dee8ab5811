armdyn_derive::robot_model!("tests/ui/fail_input_range.json");

fn main() {}
