armdyn_derive::robot_model!("tests/ui/pass_tiny.json", f16);

fn main() {}
