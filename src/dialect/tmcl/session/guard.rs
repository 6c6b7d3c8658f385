//! A TMCL session dropped during a panic stops its motors and programs and puts the modules back
//! in the mode they were found in (see [`crate::dialect::guard`]).

use crate::dialect::DialectSession;
use crate::dialect::guard::on_panic;

use super::TmclSession;

impl Drop for TmclSession {
    fn drop(&mut self) {
        on_panic(self, |session| {
            let mut restored = session.close();
            if restored.is_empty() {
                restored.push(if session.stay_ascii {
                    "modules left in ASCII mode (--stay-ascii)".to_string()
                } else {
                    "modules returned to the mode they were found in".to_string()
                });
            }
            restored
        });
    }
}
