//! How far the two values of a user/real pair may lie apart: data from `[user_real]` in
//! `data/smd4.toml`, read by the command table and used by the reply check.

/// How far the user and real value of a user/real pair may lie apart: the real value is the
/// closest the drive's clock divider can produce, so it is near the user value, never far.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RealTolerance {
    /// Fraction of the user value, including the rounding of both printed values.
    pub relative: f64,
    /// Hz or Hz/s, for values near zero.
    pub absolute: f64,
}

impl RealTolerance {
    /// The `[user_real]` tolerances, widened by one unit in the last of `float_digits`
    /// significant digits; `None` when the data gives none.
    pub(crate) fn from_data(
        relative: Option<f64>,
        absolute: Option<f64>,
        float_digits: u32,
    ) -> Result<Option<RealTolerance>, String> {
        let (Some(relative), Some(absolute)) = (relative, absolute) else {
            return match (relative, absolute) {
                (None, None) => Ok(None),
                _ => Err("[user_real] needs both relative_tolerance and absolute_tolerance".into()),
            };
        };
        if !(relative >= 0.0 && absolute >= 0.0 && relative.is_finite() && absolute.is_finite()) {
            return Err("[user_real] tolerances must be finite and not negative".into());
        }
        let rounding = 10f64.powi(1 - float_digits.max(1) as i32);
        Ok(Some(RealTolerance {
            relative: relative + rounding,
            absolute,
        }))
    }

    /// Whether `real` may be what the drive produces for `user`.
    pub fn admits(&self, user: f64, real: f64) -> bool {
        let scale = user.abs().max(real.abs());
        (user - real).abs() <= (self.relative * scale).max(self.absolute)
    }
}
