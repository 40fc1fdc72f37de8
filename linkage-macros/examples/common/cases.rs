//! The mechanisms whose cost the examples measure, as the text of their
//! attribute and struct: the worksheet's four-bar, the two-loop six-bar and
//! chains of N coupled four-bar loops.

/// A mechanism as the text of its attribute and struct.
pub struct Case {
    pub name: String,
    pub n: Option<usize>,
    pub attr: String,
    pub item: String,
}

pub fn fourbar() -> Case {
    Case {
        name: "four-bar (worksheet)".into(),
        n: None,
        attr: "u = [theta3, theta4], v = [theta2],
            points = [
                B = (l2 * theta2.cos(), l2 * theta2.sin()),
                C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
                G2 = (0.5 * B.x, 0.5 * B.y),
                G3 = (0.5 * (B.x + C.x), 0.5 * (B.y + C.y)),
                G4 = (C.x + 0.5 * l4 * theta4.cos(), C.y + 0.5 * l4 * theta4.sin()),
            ],
            closure = [
                l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
                l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
            ]"
        .into(),
        item: "pub struct Mechanism { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64 }".into(),
    }
}

pub fn sixbar() -> Case {
    Case {
        name: "six-bar (two loops)".into(),
        n: None,
        attr: "u = [theta3, theta4, theta5, theta6], v = [theta2],
            points = [
                B = (l2 * theta2.cos(), l2 * theta2.sin()),
                C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
                E = (B.x + e * (theta3 + beta).cos(), B.y + e * (theta3 + beta).sin()),
                F = (E.x + l5 * theta5.cos(), E.y + l5 * theta5.sin()),
            ],
            closure = [
                l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
                l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
                E.x + l5 * theta5.cos() - gx - l6 * theta6.cos(),
                E.y + l5 * theta5.sin() - gy - l6 * theta6.sin(),
            ]"
        .into(),
        item: "pub struct Mechanism { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64, pub e: f64, \
               pub beta: f64, pub l5: f64, pub l6: f64, pub gx: f64, pub gy: f64 }"
            .into(),
    }
}

/// N four-bar loops in a chain: the crank of loop k is keyed to the rocker
/// of loop k − 1 (at an angle offset), its ground pivots shifted along x;
/// each loop has a coupler point. m = 2N.
pub fn chain(n: usize) -> Case {
    let mut u = Vec::new();
    let mut points = Vec::new();
    let mut closure = Vec::new();
    for k in 1..=n {
        u.push(format!("a{k}"));
        u.push(format!("b{k}"));
        let crank = if k == 1 {
            "t".to_owned()
        } else {
            format!("(b{} + delta)", k - 1)
        };
        let x0 = format!("{}.0 * l1", k - 1);
        points.push(format!(
            "P{k} = ({x0} + l2 * {crank}.cos() + e * (a{k} + beta).cos(), l2 * {crank}.sin() + e * (a{k} + beta).sin())"
        ));
        closure.push(format!(
            "l2 * {crank}.cos() + l3 * a{k}.cos() + l4 * b{k}.cos() - l1"
        ));
        closure.push(format!(
            "l2 * {crank}.sin() + l3 * a{k}.sin() + l4 * b{k}.sin()"
        ));
    }
    Case {
        name: format!("chain N = {n}"),
        n: Some(n),
        attr: format!(
            "u = [{}], v = [t], points = [{}], closure = [{}]",
            u.join(", "),
            points.join(", "),
            closure.join(", ")
        ),
        item: "pub struct Mechanism { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64, pub e: f64, \
               pub beta: f64, pub delta: f64 }"
            .into(),
    }
}
