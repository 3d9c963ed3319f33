//! The Taylor configuration of the lanes and ensemble benches at a tolerance: Jorba and Zou's
//! order, or the order of least work with `PRECESS_ORDER_RULE=minimum-work` (included by path).

use precess::taylor::{OrderRule, TaylorConfig};

/// `TaylorConfig::with_tol(tol, tol)` under the order rule `PRECESS_ORDER_RULE` names
/// (`jorba-zou`, the default, or `minimum-work`); any other value stops the bench.
pub fn taylor_config(tol: f64) -> TaylorConfig {
    let order_rule = match std::env::var("PRECESS_ORDER_RULE").as_deref() {
        Err(_) | Ok("jorba-zou") => OrderRule::JorbaZou,
        Ok("minimum-work") => OrderRule::MinimumWork,
        Ok(other) => panic!("PRECESS_ORDER_RULE={other}: expected jorba-zou or minimum-work"),
    };
    TaylorConfig {
        order_rule,
        ..TaylorConfig::with_tol(tol, tol)
    }
}
