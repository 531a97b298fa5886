// Placeholder, replaced by hole capping.
