//! Tests of `armdyn::control::safety`: the force watch, the sensor health check and the monitor.

mod force_watch;
mod monitor;
mod sensor_health;
