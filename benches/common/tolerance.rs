//! The Taylor configuration of the lanes and ensemble benches at a tolerance: the default order
//! of least work, or Jorba and Zou's with `PRECESS_ORDER_RULE=jorba-zou` (included by path).

use precess::taylor::{OrderRule, TaylorConfig};

/// `TaylorConfig::with_tol(tol, tol)` under the order rule `PRECESS_ORDER_RULE` names
/// (`minimum-work`, the default, or `jorba-zou`); any other value stops the bench.
pub fn taylor_config(tol: f64) -> TaylorConfig {
    let order_rule = match std::env::var("PRECESS_ORDER_RULE").as_deref() {
        Err(_) | Ok("minimum-work") => OrderRule::MinimumWork,
        Ok("jorba-zou") => OrderRule::JorbaZou,
        Ok(other) => panic!("PRECESS_ORDER_RULE={other}: expected jorba-zou or minimum-work"),
    };
    TaylorConfig {
        order_rule,
        ..TaylorConfig::with_tol(tol, tol)
    }
}
