"""Gear trains: planetary synthesis, the velocity plan of a train and the involute pair."""
