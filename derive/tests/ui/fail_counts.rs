armdyn_derive::robot_model!("tests/ui/fail_counts.json");

fn main() {}
