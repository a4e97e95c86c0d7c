"""Plans emitted group by group: position, velocity, acceleration (force in a later module)."""
