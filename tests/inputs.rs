//! Inputs and files checked at the door, through the real binary: module profiles refused with
//! the line of each problem, and a custom profile served by the built-in simulator.

mod profile;
