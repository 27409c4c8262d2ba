# Figure rules, included by the top-level Makefile (which defines OUT, BIN, PY
# and FIGS before the include). One rule per data set, one per figure.
#
# Template for a new driver <drv> writing $(OUT)/data/<drv>/ and
# $(OUT)/claims/<drv>.csv, drawn by figures/<figNN>.py:
#
#   $(OUT)/data/<drv>/.done: $(BIN)/<drv>
#   	$(BIN)/<drv> --out $(OUT)
#   	@touch $@
#
#   $(OUT)/figures/<figNN>.png: $(OUT)/data/<drv>/.done figures/<figNN>.py
#   	$(PY) figures/<figNN>.py $(OUT)/data/<drv> $@
#
#   FIGS += $(OUT)/figures/<figNN>.png
#   $(OUT)/report.md: $(OUT)/data/<drv>/.done
#
# The last line re-makes the report when the driver re-ran, even for a driver
# with no figure (the Makefile's $(wildcard $(OUT)/claims/*.csv) is expanded
# before the drivers run, so it misses claim files created in the same run).
#
# The .done stamp is touched only after the driver succeeds, so a failed run
# is retried next time; drivers write every file atomically (CsvWriter), so a
# failure never leaves half a CSV. A figure script also gets a rule on any
# helper module it imports (figures/potential_common.py, figures/paper_common.py
# with the papers' stated values, below).

# --- Paper A Sects. 3.1.2, 3.2.1: entrance block, force as energy gradient ---
$(OUT)/data/contact_statements/.done: $(BIN)/contact_statements
	$(BIN)/contact_statements --out $(OUT)
	@touch $@

$(OUT)/figures/fig_contact_statements.png: $(OUT)/data/contact_statements/.done figures/fig_contact_statements.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig_contact_statements.py $(OUT)/data/contact_statements $@

FIGS += $(OUT)/figures/fig_contact_statements.png
$(OUT)/report.md: $(OUT)/data/contact_statements/.done

# --- Paper A Sect. 3.1.3: intersection polygon against CGAL (no figure) -------
# (the program lives in property_tests/, the only directory that links CGAL)
$(OUT)/data/exact_geometry/.done: $(BIN)/geometry_claims
	$(BIN)/geometry_claims --out $(OUT)
	@mkdir -p $(@D) && touch $@
$(OUT)/report.md: $(OUT)/data/exact_geometry/.done

# --- Paper A Sect. 3.2.2: potential fields, Figs. 4b and 5 -------------------
$(OUT)/data/potential_fields/.done: $(BIN)/potential_fields
	$(BIN)/potential_fields --out $(OUT)
	@touch $@

$(OUT)/figures/fig04b_potential.png: $(OUT)/data/potential_fields/.done figures/fig04_potential.py figures/potential_common.py
	$(PY) figures/fig04_potential.py $(OUT)/data/potential_fields $@

$(OUT)/figures/fig05_potential.png: $(OUT)/data/potential_fields/.done figures/fig05_potential.py figures/potential_common.py
	$(PY) figures/fig05_potential.py $(OUT)/data/potential_fields $@

FIGS += $(OUT)/figures/fig04b_potential.png $(OUT)/figures/fig05_potential.png
$(OUT)/report.md: $(OUT)/data/potential_fields/.done

# --- Paper A Sect. 4.1: two squares, Fig. 8 ----------------------------------
$(OUT)/data/two_squares/.done: $(BIN)/two_squares
	$(BIN)/two_squares --out $(OUT)
	@touch $@

$(OUT)/figures/fig08_two_squares.png: $(OUT)/data/two_squares/.done figures/fig08_two_squares.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig08_two_squares.py $(OUT)/data/two_squares $@

FIGS += $(OUT)/figures/fig08_two_squares.png
$(OUT)/report.md: $(OUT)/data/two_squares/.done

# --- Paper A Sect. 4.2: symmetric stack, Fig. 10 -----------------------------
$(OUT)/data/symmetric_stack/.done: $(BIN)/symmetric_stack
	$(BIN)/symmetric_stack --out $(OUT)
	@touch $@

$(OUT)/figures/fig10_symmetric_stack.png: $(OUT)/data/symmetric_stack/.done figures/fig10_symmetric_stack.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig10_symmetric_stack.py $(OUT)/data/symmetric_stack $@

FIGS += $(OUT)/figures/fig10_symmetric_stack.png
$(OUT)/report.md: $(OUT)/data/symmetric_stack/.done

# --- Paper A Sect. 4.3: incline, Fig. 12 --------------------------------------
$(OUT)/data/incline/.done: $(BIN)/incline
	$(BIN)/incline --out $(OUT)
	@touch $@

$(OUT)/figures/fig12_incline.png: $(OUT)/data/incline/.done figures/fig12_incline.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig12_incline.py $(OUT)/data/incline $@

FIGS += $(OUT)/figures/fig12_incline.png
$(OUT)/report.md: $(OUT)/data/incline/.done

# --- Paper A Sect. 3.2.2: Fig. 4a, previous sub-polygon potential (reconstructed) --
$(OUT)/data/previous_potential/.done: $(BIN)/previous_potential
	$(BIN)/previous_potential --out $(OUT)
	@touch $@

$(OUT)/figures/fig04a_previous_potential.png: $(OUT)/data/previous_potential/.done figures/fig04a_previous_potential.py figures/potential_common.py
	$(PY) figures/fig04a_previous_potential.py $(OUT)/data/previous_potential $@

FIGS += $(OUT)/figures/fig04a_previous_potential.png
$(OUT)/report.md: $(OUT)/data/previous_potential/.done

# --- Paper A Sect. 5.1: bouncing block, Fig. 14 --------------------------------
$(OUT)/data/bouncing_block/.done: $(BIN)/bouncing_block
	$(BIN)/bouncing_block --out $(OUT)
	@touch $@

$(OUT)/figures/fig14_bouncing_block.png: $(OUT)/data/bouncing_block/.done figures/fig14_bouncing_block.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig14_bouncing_block.py $(OUT)/data/bouncing_block $@

FIGS += $(OUT)/figures/fig14_bouncing_block.png
$(OUT)/report.md: $(OUT)/data/bouncing_block/.done

# --- Paper A Sect. 5.2: small-angle triangles, Fig. 16 -------------------------
$(OUT)/data/small_angles/.done: $(BIN)/small_angles
	$(BIN)/small_angles --out $(OUT)
	@touch $@

$(OUT)/figures/fig16_small_angles.png: $(OUT)/data/small_angles/.done figures/fig16_small_angles.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig16_small_angles.py $(OUT)/data/small_angles $@

FIGS += $(OUT)/figures/fig16_small_angles.png
$(OUT)/report.md: $(OUT)/data/small_angles/.done

# --- Paper A Sect. 5.3: small edges, Fig. 18 -----------------------------------
$(OUT)/data/small_edges/.done: $(BIN)/small_edges
	$(BIN)/small_edges --out $(OUT)
	@touch $@

$(OUT)/figures/fig18_small_edges.png: $(OUT)/data/small_edges/.done figures/fig18_small_edges.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig18_small_edges.py $(OUT)/data/small_edges $@

FIGS += $(OUT)/figures/fig18_small_edges.png
$(OUT)/report.md: $(OUT)/data/small_edges/.done

# --- Beyond Sect. 5: extreme geometry, dt / dt_crit against the sizes ---------
$(OUT)/data/extreme_geometry/.done: $(BIN)/extreme_geometry
	$(BIN)/extreme_geometry --out $(OUT)
	@touch $@

$(OUT)/figures/extreme_geometry.png: $(OUT)/data/extreme_geometry/.done figures/fig_extreme_geometry.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig_extreme_geometry.py $(OUT)/data/extreme_geometry $@

FIGS += $(OUT)/figures/extreme_geometry.png
$(OUT)/report.md: $(OUT)/data/extreme_geometry/.done

# --- Beyond Sect. 3.2.3: is the paper's segmentation exact? --------------------
$(OUT)/data/segmentation/.done: $(BIN)/segmentation
	$(BIN)/segmentation --out $(OUT)
	@touch $@

$(OUT)/figures/segmentation_study.png: $(OUT)/data/segmentation/.done figures/fig_segmentation_study.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig_segmentation_study.py $(OUT)/data/segmentation $@

FIGS += $(OUT)/figures/segmentation_study.png
$(OUT)/report.md: $(OUT)/data/segmentation/.done

# --- Paper B Sect. 6: two prisms, two-scale contact, Figs. 13-16 -------------
$(OUT)/data/B_6_two_prisms/.done: $(BIN)/B_6_two_prisms
	$(BIN)/B_6_two_prisms --out $(OUT)
	@touch $@

$(OUT)/figures/figB13_15_prisms.png: $(OUT)/data/B_6_two_prisms/.done figures/figB13_15_prisms.py figures/cdem_common.py figures/potential_common.py
	$(PY) figures/figB13_15_prisms.py $(OUT)/data/B_6_two_prisms $@

$(OUT)/figures/figB16_displacement.png: $(OUT)/data/B_6_two_prisms/.done figures/figB16_displacement.py figures/cdem_common.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/figB16_displacement.py $(OUT)/data/B_6_two_prisms $@

FIGS += $(OUT)/figures/figB13_15_prisms.png $(OUT)/figures/figB16_displacement.png
$(OUT)/report.md: $(OUT)/data/B_6_two_prisms/.done

# --- Paper A vs Paper B contact on the same collisions (dt sweeps) -----------
$(OUT)/data/B_7_contact_comparison/.done: $(BIN)/B_7_contact_comparison
	$(BIN)/B_7_contact_comparison --out $(OUT)
	@touch $@

$(OUT)/figures/figB_comparison.png: $(OUT)/data/B_7_contact_comparison/.done figures/figB_comparison.py figures/cdem_common.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/figB_comparison.py $(OUT)/data/B_7_contact_comparison $@

FIGS += $(OUT)/figures/figB_comparison.png
$(OUT)/report.md: $(OUT)/data/B_7_contact_comparison/.done

# --- Beyond both papers: two elastic bars against 1D wave theory (B, B0, A) ---
$(OUT)/data/B_8_bar_waves/.done: $(BIN)/B_8_bar_waves
	$(BIN)/B_8_bar_waves --out $(OUT)
	@touch $@

$(OUT)/figures/figB_bar_waves.png: $(OUT)/data/B_8_bar_waves/.done figures/figB_bar_waves.py figures/cdem_common.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/figB_bar_waves.py $(OUT)/data/B_8_bar_waves $@

FIGS += $(OUT)/figures/figB_bar_waves.png
$(OUT)/report.md: $(OUT)/data/B_8_bar_waves/.done

# --- Beyond Paper B: impact study of the two-scale contact (oblique impacts) ---
$(OUT)/data/B_9_impact_study/.done: $(BIN)/B_9_impact_study
	$(BIN)/B_9_impact_study --out $(OUT)
	@touch $@

$(OUT)/figures/figB_impact_study.png: $(OUT)/data/B_9_impact_study/.done figures/figB_impact_study.py figures/cdem_common.py figures/potential_common.py
	$(PY) figures/figB_impact_study.py $(OUT)/data/B_9_impact_study $@

FIGS += $(OUT)/figures/figB_impact_study.png
$(OUT)/report.md: $(OUT)/data/B_9_impact_study/.done

# --- Paper A Sect. 6.1: collapse of a jointed rock column, Fig. 20 ----------
# ~75,000 steps per case (two cases): the longest driver; it prints progress.
$(OUT)/data/collapse/.done: $(BIN)/collapse
	$(BIN)/collapse --out $(OUT)
	@touch $@

$(OUT)/figures/fig20_collapse.png: $(OUT)/data/collapse/.done figures/fig20_collapse.py figures/blocks_common.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig20_collapse.py $(OUT)/data/collapse $@

$(OUT)/figures/fig20_collapse_runout.png: $(OUT)/data/collapse/.done figures/fig20_collapse.py figures/blocks_common.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig20_collapse.py --runout $(OUT)/data/collapse $@

$(OUT)/figures/anim_collapse_case1.gif: $(OUT)/data/collapse/.done figures/anim_collapse.py figures/blocks_common.py figures/potential_common.py
	$(PY) figures/anim_collapse.py $(OUT)/data/collapse case1 $@

$(OUT)/figures/anim_collapse_case2.gif: $(OUT)/data/collapse/.done figures/anim_collapse.py figures/blocks_common.py figures/potential_common.py
	$(PY) figures/anim_collapse.py $(OUT)/data/collapse case2 $@

FIGS += $(OUT)/figures/fig20_collapse.png $(OUT)/figures/fig20_collapse_runout.png \
        $(OUT)/figures/anim_collapse_case1.gif $(OUT)/figures/anim_collapse_case2.gif
$(OUT)/report.md: $(OUT)/data/collapse/.done

# --- Paper A Sect. 6.2: toppling and slumping valley slopes, Fig. 22 --------
$(OUT)/data/toppling_slumping/.done: $(BIN)/toppling_slumping
	$(BIN)/toppling_slumping --out $(OUT)
	@touch $@

$(OUT)/figures/fig22_toppling.png: $(OUT)/data/toppling_slumping/.done figures/fig22_toppling.py figures/blocks_common.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/fig22_toppling.py $(OUT)/data/toppling_slumping $@

FIGS += $(OUT)/figures/fig22_toppling.png
$(OUT)/report.md: $(OUT)/data/toppling_slumping/.done

# --- S1: work precision, error against run time --------------------------
$(OUT)/data/work_precision/.done: $(BIN)/work_precision
	$(BIN)/work_precision --out $(OUT)
	@touch $@

S1_DEPS := $(OUT)/data/work_precision/.done figures/figS1_work_precision.py figures/potential_common.py
$(OUT)/figures/figS1a_two_squares.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ 4.1
$(OUT)/figures/figS1b_incline.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ 4.3
$(OUT)/figures/figS1c_resting_block.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ resting
$(OUT)/figures/figS1d_triangles.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ 5.2
$(OUT)/figures/figS1e_bouncing_block.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ 5.1
$(OUT)/figures/figS1f_small_edge.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ 5.3
$(OUT)/figures/figS1g_free_rotation.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ free
$(OUT)/figures/figS1h_damped_flight.png: $(S1_DEPS)
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ damped

FIGS += $(OUT)/figures/figS1a_two_squares.png $(OUT)/figures/figS1b_incline.png \
        $(OUT)/figures/figS1c_resting_block.png $(OUT)/figures/figS1d_triangles.png \
        $(OUT)/figures/figS1e_bouncing_block.png $(OUT)/figures/figS1f_small_edge.png \
        $(OUT)/figures/figS1g_free_rotation.png $(OUT)/figures/figS1h_damped_flight.png
$(OUT)/report.md: $(OUT)/data/work_precision/.done

# --- S2: stability maps (kn x dt) and the dt_crit check ---------------------
$(OUT)/data/stability_maps/.done: $(BIN)/stability_maps
	$(BIN)/stability_maps --out $(OUT)
	@touch $@

$(OUT)/figures/figS2_stability_maps.png: $(OUT)/data/stability_maps/.done figures/figS2_stability_maps.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/figS2_stability_maps.py $(OUT)/data/stability_maps $@

FIGS += $(OUT)/figures/figS2_stability_maps.png
$(OUT)/report.md: $(OUT)/data/stability_maps/.done

# --- S3: extreme cases (table in the report; no figure) ---------------------
$(OUT)/data/extreme_cases/.done: $(BIN)/extreme_cases
	$(BIN)/extreme_cases --out $(OUT)
	@touch $@

$(OUT)/report.md: $(OUT)/data/extreme_cases/.done

# --- S3: penetration map (guard on and off over speed, kn and dt) ------------
$(OUT)/data/penetration_map/.done: $(BIN)/penetration_map
	$(BIN)/penetration_map --out $(OUT)
	@touch $@

$(OUT)/figures/figS3_penetration_map.png: $(OUT)/data/penetration_map/.done figures/figS3_penetration_map.py figures/potential_common.py figures/paper_common.py
	$(PY) figures/figS3_penetration_map.py $(OUT)/data/penetration_map $@

FIGS += $(OUT)/figures/figS3_penetration_map.png
$(OUT)/report.md: $(OUT)/data/penetration_map/.done
