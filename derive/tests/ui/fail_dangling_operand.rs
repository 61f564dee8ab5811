armdyn_derive::robot_model!("tests/ui/fail_dangling_operand.json");

fn main() {}
