//! Writing replies the way the options say: flag case, float digits, error spelling, the address
//! prefix, PACT/PREL number format, and the multi-line listings.

use crate::dialect::smd4::protocol::format::{
    format_error, format_fixed, format_flags, format_float, format_hms,
};
use crate::dialect::smd4::protocol::{ErrorCode, ItemType, ReplyShape, Smd4Command};

use super::Smd4Sim;
use super::config::Setting;
use super::options::PositionFormat;

/// What a command produced.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Outcome {
    /// Data items (possibly none).
    Items(Vec<String>),
    /// A multi-line reply: the flags line with an empty item, then these lines.
    Lines(Vec<String>),
    /// The error code.
    Failed(ErrorCode),
    /// No reply (SYS:PROG, SYS:RESET).
    Silent,
}

impl Smd4Sim {
    /// The bytes of a reply to a packet that carried `address`.
    pub(super) fn render(&self, t: f64, address: Option<u32>, outcome: Outcome) -> Vec<u8> {
        let s = format_flags(self.status(t).0, self.options.flag_case);
        let e = format_flags(self.eflags.0, self.options.flag_case);
        let mut head = match address {
            Some(a) if self.options.reply_prefix => format!("@{a},{s},{e}"),
            _ => format!("{s},{e}"),
        };
        let mut lines = Vec::new();
        match outcome {
            Outcome::Silent => return Vec::new(),
            Outcome::Items(items) => items.iter().for_each(|i| {
                head.push(',');
                head.push_str(i);
            }),
            Outcome::Failed(code) => {
                head.push(',');
                head.push_str(&format_error(code, self.options.error_spelling));
            }
            Outcome::Lines(more) => {
                head.push(',');
                lines = more;
            }
        }
        let mut text = head + "\r\n";
        for line in lines {
            text.push_str(&line);
            text.push_str("\r\n");
        }
        text.into_bytes()
    }

    /// A failure reply without executing anything (malformed packets).
    pub(super) fn failure(&self, t: f64, address: Option<u32>, code: ErrorCode) -> Vec<u8> {
        self.render(t, address, Outcome::Failed(code))
    }

    /// The data items for `value` in the command's reply shape.
    pub(super) fn items(&self, spec: &Smd4Command, value: Option<&Setting>) -> Vec<String> {
        match (&spec.reply, value) {
            (ReplyShape::Literal(_), _)
                if spec.reply_optional && self.options.omit_optional_item =>
            {
                Vec::new()
            }
            (ReplyShape::Literal(text), _) => vec![text.clone()],
            (ReplyShape::Value, Some(v)) => vec![self.item(spec, v)],
            (ReplyShape::UserReal, Some(v)) => {
                let user = v.number();
                let real = match self.options.real_value_grid {
                    Some(step) if step > 0.0 => (user / step).round() * step,
                    _ => user,
                };
                vec![self.float(user), self.float(real)]
            }
            (ReplyShape::Named, Some(v)) => {
                let number = v.text();
                let label = spec.label_of(&number).unwrap_or("Unknown");
                vec![format!("{number} ({label})")]
            }
            _ => Vec::new(),
        }
    }

    fn item(&self, spec: &Smd4Command, value: &Setting) -> String {
        match spec.value_item_type() {
            Some(ItemType::Float) => {
                let x = value.number();
                if spec.fixed_point && self.options.position_format == PositionFormat::Fixed {
                    format_fixed(x)
                } else if spec.mnemonic == "MOTOR:TZW" && self.options.tzw_reply_ms {
                    self.float(x * 1000.0)
                } else {
                    self.float(x)
                }
            }
            Some(ItemType::Int | ItemType::Uint | ItemType::Bool | ItemType::Enum) => {
                format!("{}", value.number() as i64)
            }
            Some(ItemType::Hms) => format_hms(value.number().max(0.0) as u64),
            _ => value.text(),
        }
    }

    pub(super) fn float(&self, x: f64) -> String {
        format_float(x, self.options.float_style)
    }

    /// SYS:FLAGSV: a header and one `[X]Label` line per bit, for each word.
    pub(super) fn flag_listing(&self, t: f64) -> Vec<String> {
        let mut lines = vec!["-------Status flags------".to_string()];
        lines.extend(self.spec.sflags.listing(self.status(t).0));
        lines.push("-------Error flags-------".into());
        lines.extend(self.spec.eflags.listing(self.eflags.0));
        lines
    }

    /// COMS:NET:IPCONF, laid out as the document's example.
    pub(super) fn ip_summary(&self) -> Vec<String> {
        let dhcp = self.number("COMS:NET:DHCP") == 1.0;
        vec![
            "Ethernet interface:".into(),
            format!(
                "IPv4 Address. . . . . . . . . . . :{}",
                self.network("COMS:NET:IP")
            ),
            format!(
                "Subnet Mask . . . . . . . . . . .:{}",
                self.network("COMS:NET:NETMASK")
            ),
            format!(
                "Default Gateway . . . . . . . :{}",
                self.network("COMS:NET:GATEWAY")
            ),
            format!(
                "DHCP State. . . . . . . . . . . . :{}",
                if dhcp { "Enabled" } else { "Disabled" }
            ),
        ]
    }

    /// The address in effect: the DHCP lease while DHCP is on, else the static setting.
    pub(super) fn network(&self, mnemonic: &str) -> String {
        if self.number("COMS:NET:DHCP") == 1.0 {
            let sim = &self.spec.sim;
            let leased = match mnemonic {
                "COMS:NET:IP" => sim.dhcp_ip,
                "COMS:NET:NETMASK" => sim.dhcp_netmask,
                _ => sim.dhcp_gateway,
            };
            return leased.to_string();
        }
        self.working
            .get(mnemonic)
            .map(Setting::text)
            .unwrap_or_default()
    }
}
