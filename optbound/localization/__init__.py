"""Robot localization models built from the lower layers ([HS96], [BH], [LJMW97], ...)."""
