armdyn_derive::robot_model!("tests/ui/fail_result_length.json");

fn main() {}
