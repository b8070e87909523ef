// Removed once the first panel lands.
