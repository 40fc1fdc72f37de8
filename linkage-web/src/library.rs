//! The repository's library of mechanisms, built into the page so that it
//! opens them with no network: each file's path and text.

/// `(path, text)` of every file of `mechanisms/`.
pub const FILES: &[(&str, &str)] = &[
    (
        "four_bar.toml",
        include_str!("../../mechanisms/four_bar.toml"),
    ),
    (
        "slider_crank.toml",
        include_str!("../../mechanisms/slider_crank.toml"),
    ),
    (
        "five_bar.toml",
        include_str!("../../mechanisms/five_bar.toml"),
    ),
    (
        "six_bar.toml",
        include_str!("../../mechanisms/six_bar.toml"),
    ),
    (
        "watt_six_bar.toml",
        include_str!("../../mechanisms/watt_six_bar.toml"),
    ),
    (
        "stephenson_three.toml",
        include_str!("../../mechanisms/stephenson_three.toml"),
    ),
    (
        "jansen_leg.toml",
        include_str!("../../mechanisms/jansen_leg.toml"),
    ),
    (
        "quick_return.toml",
        include_str!("../../mechanisms/quick_return.toml"),
    ),
    ("shaper.toml", include_str!("../../mechanisms/shaper.toml")),
    (
        "trammel.toml",
        include_str!("../../mechanisms/trammel.toml"),
    ),
    ("boom.toml", include_str!("../../mechanisms/boom.toml")),
    (
        "coupler.toml",
        include_str!("../../mechanisms/coupler.toml"),
    ),
    (
        "slider_driven.toml",
        include_str!("../../mechanisms/slider_driven.toml"),
    ),
    (
        "joints/four_bar.toml",
        include_str!("../../mechanisms/joints/four_bar.toml"),
    ),
    (
        "joints/slider_crank.toml",
        include_str!("../../mechanisms/joints/slider_crank.toml"),
    ),
    (
        "joints/quick_return.toml",
        include_str!("../../mechanisms/joints/quick_return.toml"),
    ),
    (
        "joints/shaper.toml",
        include_str!("../../mechanisms/joints/shaper.toml"),
    ),
    (
        "joints/jansen_double.toml",
        include_str!("../../mechanisms/joints/jansen_double.toml"),
    ),
];

#[cfg(test)]
mod tests {
    /// Every file of `mechanisms/` is in the page's library.
    #[test]
    fn the_library_is_the_repositorys() {
        let mut on_disk = Vec::new();
        for folder in ["", "joints/"] {
            let dir = format!("{}/../mechanisms/{folder}", env!("CARGO_MANIFEST_DIR"));
            for entry in std::fs::read_dir(dir).unwrap() {
                let name = entry.unwrap().file_name().into_string().unwrap();
                if name.ends_with(".toml") {
                    on_disk.push(format!("{folder}{name}"));
                }
            }
        }
        on_disk.sort();
        let mut built: Vec<String> = super::FILES.iter().map(|(p, _)| p.to_string()).collect();
        built.sort();
        assert_eq!(built, on_disk);
    }
}
