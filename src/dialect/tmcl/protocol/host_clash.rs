//! Shared-bus sanity: every reply starts with the host address (global parameter 76, 2 by
//! default), and every module on an RS-485 line hears every reply. A module whose own address is
//! another module's host address takes that module's replies for commands to itself and answers
//! them, garbling the line (and acting on what it read). A scan reads each module's host address,
//! where the module's profile has the parameter, and warns about such a pair.

use super::ModuleName;

/// The host address parameter: global parameter 76 of bank 0.
pub const HOST_ADDRESS: (u8, u8) = (0, 76);

/// One warning for each module whose address is the host address another module replies to:
/// `found` holds each module's address and host address, where it was read.
pub fn warnings(found: &[(u8, Option<u8>)]) -> Vec<String> {
    let mut out = Vec::new();
    for &(module, host) in found {
        let Some(host) = host else { continue };
        let Some(&(listener, _)) = found.iter().find(|&&(a, _)| a == host && a != module) else {
            continue;
        };
        let (module, listener) = (ModuleName(module), ModuleName(listener));
        out.push(format!(
            "{listener} is at the host address of {module} ({host}, global parameter 76): on a \
             shared RS-485 line it takes {module}'s replies for commands and answers them, \
             garbling the line; give {module} a host address no module has (SGP 76, 0, N and \
             STGP 76, 0) or move {listener} to a free address (SGP 66, 0, N and STGP 66, 0)"
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_module_at_another_modules_host_address_is_warned_about_once_per_pair() {
        let found = [(1, Some(2)), (2, Some(2)), (3, None), (4, Some(100))];
        let w = warnings(&found);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].starts_with("module 2 (B) is at the host address of module 1 (A) (2, "));
        assert!(warnings(&[(1, Some(2)), (3, Some(2))]).is_empty());
        assert!(
            warnings(&[(2, Some(2))]).is_empty(),
            "its own replies it does not hear"
        );
    }
}
