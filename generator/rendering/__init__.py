"""Display rendering transforms: the ACES output transforms in float64."""
