use linkage::prelude::*;

#[linkage::linkage(
    u = [theta3, theta4],
    v = [theta2],
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
    ],
)]
#[derive(Clone, Debug)]
pub struct FourBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
}

#[test]
fn smoke() {
    let bar = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
    };
    let a = bar
        .analyze(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &vector![20f64.to_radians()],
            &vector![400.0 * std::f64::consts::TAU / 60.0],
            &vector![0.0],
            &Options::default(),
        )
        .unwrap();
    println!("{a:#?}");
    println!("{}", FourBar::SYMBOLIC);
}
