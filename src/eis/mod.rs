//! Electrochemical impedance: linearised frequency response of the discretised models.
