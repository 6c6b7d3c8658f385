//! Tests of the SMD4 protocol against the document: every example, every validation error.

mod checks;
mod examples;
mod responses;
mod validation;
