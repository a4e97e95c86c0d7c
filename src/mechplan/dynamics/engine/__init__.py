"""Dynamics of an internal-combustion engine: forces along the cylinders, torque, crank-pin
loads."""
