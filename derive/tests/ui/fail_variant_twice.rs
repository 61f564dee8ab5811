armdyn_derive::robot_model!("tests/ui/pass_tiny.json", f32, lanes, f32);

fn main() {}
