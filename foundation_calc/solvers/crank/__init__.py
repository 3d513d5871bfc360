"""Foundation of a crank-slider mechanism (Krichever & Makarov): frequencies, resonances, response."""
