module top$lanes$0$shader(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0 = 'h0;
    wire  normal$q_neg$1 = 'h0;
    wire  normal$q_neg$2 = 'h0;
    wire  [6:0] normal$q_mag$0 = 'h0;
    wire  [6:0] normal$q_mag$1 = 'h0;
    wire  [6:0] normal$q_mag$2 = 'h0;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [6:0] lighting$q_mag$0;
    reg  [6:0] lighting$q_mag$1;
    reg  [6:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse = 'h0;
    wire  [15:0] lighting$specular = 'h0;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] alpha_q$9$d;
    wire  [15:0] alpha_q$9$q;
    reg  alpha_q$9$clock;
    reg  [15:0] alpha_q$10$d;
    wire  [15:0] alpha_q$10$q;
    reg  alpha_q$10$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  [15:0] value_q$14$d;
    wire  [15:0] value_q$14$q;
    reg  value_q$14$clock;
    reg  [15:0] value_q$15$d;
    wire  [15:0] value_q$15$q;
    reg  value_q$15$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  valid_q$15$d;
    wire  valid_q$15$q;
    reg  valid_q$15$clock;
    reg  valid_q$16$d;
    wire  valid_q$16$q;
    reg  valid_q$16$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    reg  [15:0] lit_r$c;
    wire  [15:0] lit_r$y = 'h0;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    reg  [15:0] lit_g$c;
    wire  [15:0] lit_g$y = 'h0;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    reg  [15:0] lit_b$c;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    
    // Sub module instances
    top$lanes$0$shader$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$lanes$0$shader$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$lanes$0$shader$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$lanes$0$shader$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$lanes$0$shader$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$lanes$0$shader$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$lanes$0$shader$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$lanes$0$shader$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$lanes$0$shader$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$lanes$0$shader$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$lanes$0$shader$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$lanes$0$shader$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$lanes$0$shader$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$lanes$0$shader$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$lanes$0$shader$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$lanes$0$shader$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$lanes$0$shader$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$lanes$0$shader$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$lanes$0$shader$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$lanes$0$shader$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$lanes$0$shader$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$lanes$0$shader$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$lanes$0$shader$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$lanes$0$shader$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$lanes$0$shader$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$lanes$0$shader$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$lanes$0$shader$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$lanes$0$shader$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$lanes$0$shader$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$lanes$0$shader$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$lanes$0$shader$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$lanes$0$shader$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$lanes$0$shader$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$lanes$0$shader$alpha_q$9 alpha_q$9(
        .d(alpha_q$9$d),
        .q(alpha_q$9$q),
        .clock(alpha_q$9$clock)
    );
    top$lanes$0$shader$alpha_q$10 alpha_q$10(
        .d(alpha_q$10$d),
        .q(alpha_q$10$q),
        .clock(alpha_q$10$clock)
    );
    top$lanes$0$shader$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$lanes$0$shader$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$lanes$0$shader$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$lanes$0$shader$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$lanes$0$shader$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$lanes$0$shader$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$lanes$0$shader$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$lanes$0$shader$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$lanes$0$shader$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$lanes$0$shader$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$lanes$0$shader$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$lanes$0$shader$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$lanes$0$shader$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$lanes$0$shader$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$lanes$0$shader$value_q$14 value_q$14(
        .d(value_q$14$d),
        .q(value_q$14$q),
        .clock(value_q$14$clock)
    );
    top$lanes$0$shader$value_q$15 value_q$15(
        .d(value_q$15$d),
        .q(value_q$15$q),
        .clock(value_q$15$clock)
    );
    top$lanes$0$shader$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$lanes$0$shader$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$lanes$0$shader$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$lanes$0$shader$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$lanes$0$shader$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$lanes$0$shader$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$lanes$0$shader$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$lanes$0$shader$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$lanes$0$shader$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$lanes$0$shader$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$lanes$0$shader$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$lanes$0$shader$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$lanes$0$shader$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$lanes$0$shader$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$lanes$0$shader$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$lanes$0$shader$valid_q$15 valid_q$15(
        .d(valid_q$15$d),
        .q(valid_q$15$q),
        .clock(valid_q$15$clock)
    );
    top$lanes$0$shader$valid_q$16 valid_q$16(
        .d(valid_q$16$d),
        .q(valid_q$16$q),
        .clock(valid_q$16$clock)
    );
    top$lanes$0$shader$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$lanes$0$shader$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$lanes$0$shader$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$lanes$0$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$0$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$0$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$0$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        lut_q$1$clock = clock;
        lut_q$2$clock = clock;
        lut_q$3$clock = clock;
        lut_q$4$clock = clock;
        lut_q$5$clock = clock;
        lut_q$6$clock = clock;
        lut_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$0$clock = clock;
        alpha_q$1$clock = clock;
        alpha_q$2$clock = clock;
        alpha_q$3$clock = clock;
        alpha_q$4$clock = clock;
        alpha_q$5$clock = clock;
        alpha_q$6$clock = clock;
        alpha_q$7$clock = clock;
        alpha_q$8$clock = clock;
        alpha_q$9$clock = clock;
        alpha_q$10$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        value_q$14$clock = clock;
        value_q$15$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        valid_q$15$clock = clock;
        valid_q$16$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        value_q$14$d = value_q$13$q;
        value_q$15$d = value_q$14$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        valid_q$15$d = valid_q$14$q;
        valid_q$16$d = valid_q$15$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        alpha_q$9$d = alpha_q$8$q;
        alpha_q$10$d = alpha_q$9$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        lit_r$c = specular;
        lit_g$c = specular;
        lit_b$c = specular;
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = lit_r$y;
        shaded_q$1$d = lit_g$y;
        shaded_q$2$d = lit_b$y;
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$8$q;
        mul_g$b = alpha_q$8$q;
        mul_b$b = alpha_q$8$q;
        if (scalar) begin
            r_q$d = value_q$15$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$10$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$10$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$16$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$0$shader
module top$lanes$0$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$a_q
module top$lanes$0$shader$alpha_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$0
module top$lanes$0$shader$alpha_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$1
module top$lanes$0$shader$alpha_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$10
module top$lanes$0$shader$alpha_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$2
module top$lanes$0$shader$alpha_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$3
module top$lanes$0$shader$alpha_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$4
module top$lanes$0$shader$alpha_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$5
module top$lanes$0$shader$alpha_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$6
module top$lanes$0$shader$alpha_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$7
module top$lanes$0$shader$alpha_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$8
module top$lanes$0$shader$alpha_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$alpha_q$9
module top$lanes$0$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$b_q
module top$lanes$0$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$g_q
module top$lanes$0$shader$gate_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$gate_q$0
module top$lanes$0$shader$gate_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$gate_q$1
module top$lanes$0$shader$gate_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$gate_q$2
module top$lanes$0$shader$gate_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$gate_q$3
module top$lanes$0$shader$gate_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$gate_q$4
module top$lanes$0$shader$lut_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$0
module top$lanes$0$shader$lut_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$1
module top$lanes$0$shader$lut_q$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$2
module top$lanes$0$shader$lut_q$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$3
module top$lanes$0$shader$lut_q$4(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$4
module top$lanes$0$shader$lut_q$5(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$5
module top$lanes$0$shader$lut_q$6(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$6
module top$lanes$0$shader$lut_q$7(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$7
module top$lanes$0$shader$lut_q$8(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$lut_q$8
module top$lanes$0$shader$mag_in$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$mag_in$0
module top$lanes$0$shader$mag_in$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$mag_in$1
module top$lanes$0$shader$mag_in$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$mag_in$2
module top$lanes$0$shader$neg_in$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$neg_in$0
module top$lanes$0$shader$neg_in$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$neg_in$1
module top$lanes$0$shader$neg_in$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$neg_in$2
module top$lanes$0$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$r_q
module top$lanes$0$shader$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$row_q$0
module top$lanes$0$shader$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$row_q$1
module top$lanes$0$shader$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$row_q$2
module top$lanes$0$shader$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$row_q$3
module top$lanes$0$shader$shaded_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$shaded_q$0
module top$lanes$0$shader$shaded_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$shaded_q$1
module top$lanes$0$shader$shaded_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$shaded_q$2
module top$lanes$0$shader$valid_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$0
module top$lanes$0$shader$valid_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$1
module top$lanes$0$shader$valid_q$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$10
module top$lanes$0$shader$valid_q$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$11
module top$lanes$0$shader$valid_q$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$12
module top$lanes$0$shader$valid_q$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$13
module top$lanes$0$shader$valid_q$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$14
module top$lanes$0$shader$valid_q$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$15
module top$lanes$0$shader$valid_q$16(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$16
module top$lanes$0$shader$valid_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$2
module top$lanes$0$shader$valid_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$3
module top$lanes$0$shader$valid_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$4
module top$lanes$0$shader$valid_q$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$5
module top$lanes$0$shader$valid_q$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$6
module top$lanes$0$shader$valid_q$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$7
module top$lanes$0$shader$valid_q$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$8
module top$lanes$0$shader$valid_q$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q$9
module top$lanes$0$shader$value_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$0
module top$lanes$0$shader$value_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$1
module top$lanes$0$shader$value_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$10
module top$lanes$0$shader$value_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$11
module top$lanes$0$shader$value_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$12
module top$lanes$0$shader$value_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$13
module top$lanes$0$shader$value_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$14
module top$lanes$0$shader$value_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$15
module top$lanes$0$shader$value_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$2
module top$lanes$0$shader$value_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$3
module top$lanes$0$shader$value_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$4
module top$lanes$0$shader$value_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$5
module top$lanes$0$shader$value_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$6
module top$lanes$0$shader$value_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$7
module top$lanes$0$shader$value_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$8
module top$lanes$0$shader$value_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$value_q$9
module top$lanes$1$shader(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0 = 'h0;
    wire  normal$q_neg$1 = 'h0;
    wire  normal$q_neg$2 = 'h0;
    wire  [6:0] normal$q_mag$0 = 'h0;
    wire  [6:0] normal$q_mag$1 = 'h0;
    wire  [6:0] normal$q_mag$2 = 'h0;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [6:0] lighting$q_mag$0;
    reg  [6:0] lighting$q_mag$1;
    reg  [6:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse = 'h0;
    wire  [15:0] lighting$specular = 'h0;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] alpha_q$9$d;
    wire  [15:0] alpha_q$9$q;
    reg  alpha_q$9$clock;
    reg  [15:0] alpha_q$10$d;
    wire  [15:0] alpha_q$10$q;
    reg  alpha_q$10$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  [15:0] value_q$14$d;
    wire  [15:0] value_q$14$q;
    reg  value_q$14$clock;
    reg  [15:0] value_q$15$d;
    wire  [15:0] value_q$15$q;
    reg  value_q$15$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  valid_q$15$d;
    wire  valid_q$15$q;
    reg  valid_q$15$clock;
    reg  valid_q$16$d;
    wire  valid_q$16$q;
    reg  valid_q$16$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    reg  [15:0] lit_r$c;
    wire  [15:0] lit_r$y = 'h0;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    reg  [15:0] lit_g$c;
    wire  [15:0] lit_g$y = 'h0;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    reg  [15:0] lit_b$c;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    
    // Sub module instances
    top$lanes$1$shader$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$lanes$1$shader$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$lanes$1$shader$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$lanes$1$shader$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$lanes$1$shader$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$lanes$1$shader$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$lanes$1$shader$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$lanes$1$shader$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$lanes$1$shader$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$lanes$1$shader$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$lanes$1$shader$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$lanes$1$shader$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$lanes$1$shader$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$lanes$1$shader$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$lanes$1$shader$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$lanes$1$shader$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$lanes$1$shader$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$lanes$1$shader$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$lanes$1$shader$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$lanes$1$shader$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$lanes$1$shader$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$lanes$1$shader$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$lanes$1$shader$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$lanes$1$shader$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$lanes$1$shader$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$lanes$1$shader$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$lanes$1$shader$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$lanes$1$shader$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$lanes$1$shader$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$lanes$1$shader$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$lanes$1$shader$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$lanes$1$shader$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$lanes$1$shader$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$lanes$1$shader$alpha_q$9 alpha_q$9(
        .d(alpha_q$9$d),
        .q(alpha_q$9$q),
        .clock(alpha_q$9$clock)
    );
    top$lanes$1$shader$alpha_q$10 alpha_q$10(
        .d(alpha_q$10$d),
        .q(alpha_q$10$q),
        .clock(alpha_q$10$clock)
    );
    top$lanes$1$shader$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$lanes$1$shader$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$lanes$1$shader$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$lanes$1$shader$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$lanes$1$shader$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$lanes$1$shader$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$lanes$1$shader$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$lanes$1$shader$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$lanes$1$shader$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$lanes$1$shader$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$lanes$1$shader$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$lanes$1$shader$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$lanes$1$shader$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$lanes$1$shader$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$lanes$1$shader$value_q$14 value_q$14(
        .d(value_q$14$d),
        .q(value_q$14$q),
        .clock(value_q$14$clock)
    );
    top$lanes$1$shader$value_q$15 value_q$15(
        .d(value_q$15$d),
        .q(value_q$15$q),
        .clock(value_q$15$clock)
    );
    top$lanes$1$shader$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$lanes$1$shader$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$lanes$1$shader$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$lanes$1$shader$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$lanes$1$shader$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$lanes$1$shader$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$lanes$1$shader$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$lanes$1$shader$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$lanes$1$shader$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$lanes$1$shader$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$lanes$1$shader$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$lanes$1$shader$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$lanes$1$shader$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$lanes$1$shader$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$lanes$1$shader$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$lanes$1$shader$valid_q$15 valid_q$15(
        .d(valid_q$15$d),
        .q(valid_q$15$q),
        .clock(valid_q$15$clock)
    );
    top$lanes$1$shader$valid_q$16 valid_q$16(
        .d(valid_q$16$d),
        .q(valid_q$16$q),
        .clock(valid_q$16$clock)
    );
    top$lanes$1$shader$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$lanes$1$shader$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$lanes$1$shader$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$lanes$1$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$1$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$1$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$1$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        lut_q$1$clock = clock;
        lut_q$2$clock = clock;
        lut_q$3$clock = clock;
        lut_q$4$clock = clock;
        lut_q$5$clock = clock;
        lut_q$6$clock = clock;
        lut_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$0$clock = clock;
        alpha_q$1$clock = clock;
        alpha_q$2$clock = clock;
        alpha_q$3$clock = clock;
        alpha_q$4$clock = clock;
        alpha_q$5$clock = clock;
        alpha_q$6$clock = clock;
        alpha_q$7$clock = clock;
        alpha_q$8$clock = clock;
        alpha_q$9$clock = clock;
        alpha_q$10$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        value_q$14$clock = clock;
        value_q$15$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        valid_q$15$clock = clock;
        valid_q$16$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        value_q$14$d = value_q$13$q;
        value_q$15$d = value_q$14$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        valid_q$15$d = valid_q$14$q;
        valid_q$16$d = valid_q$15$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        alpha_q$9$d = alpha_q$8$q;
        alpha_q$10$d = alpha_q$9$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        lit_r$c = specular;
        lit_g$c = specular;
        lit_b$c = specular;
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = lit_r$y;
        shaded_q$1$d = lit_g$y;
        shaded_q$2$d = lit_b$y;
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$8$q;
        mul_g$b = alpha_q$8$q;
        mul_b$b = alpha_q$8$q;
        if (scalar) begin
            r_q$d = value_q$15$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$10$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$10$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$16$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$1$shader
module top$lanes$1$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$a_q
module top$lanes$1$shader$alpha_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$0
module top$lanes$1$shader$alpha_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$1
module top$lanes$1$shader$alpha_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$10
module top$lanes$1$shader$alpha_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$2
module top$lanes$1$shader$alpha_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$3
module top$lanes$1$shader$alpha_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$4
module top$lanes$1$shader$alpha_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$5
module top$lanes$1$shader$alpha_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$6
module top$lanes$1$shader$alpha_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$7
module top$lanes$1$shader$alpha_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$8
module top$lanes$1$shader$alpha_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$alpha_q$9
module top$lanes$1$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$b_q
module top$lanes$1$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$g_q
module top$lanes$1$shader$gate_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$gate_q$0
module top$lanes$1$shader$gate_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$gate_q$1
module top$lanes$1$shader$gate_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$gate_q$2
module top$lanes$1$shader$gate_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$gate_q$3
module top$lanes$1$shader$gate_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$gate_q$4
module top$lanes$1$shader$lut_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$0
module top$lanes$1$shader$lut_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$1
module top$lanes$1$shader$lut_q$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$2
module top$lanes$1$shader$lut_q$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$3
module top$lanes$1$shader$lut_q$4(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$4
module top$lanes$1$shader$lut_q$5(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$5
module top$lanes$1$shader$lut_q$6(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$6
module top$lanes$1$shader$lut_q$7(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$7
module top$lanes$1$shader$lut_q$8(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$lut_q$8
module top$lanes$1$shader$mag_in$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$mag_in$0
module top$lanes$1$shader$mag_in$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$mag_in$1
module top$lanes$1$shader$mag_in$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$mag_in$2
module top$lanes$1$shader$neg_in$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$neg_in$0
module top$lanes$1$shader$neg_in$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$neg_in$1
module top$lanes$1$shader$neg_in$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$neg_in$2
module top$lanes$1$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$r_q
module top$lanes$1$shader$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$row_q$0
module top$lanes$1$shader$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$row_q$1
module top$lanes$1$shader$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$row_q$2
module top$lanes$1$shader$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$row_q$3
module top$lanes$1$shader$shaded_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$shaded_q$0
module top$lanes$1$shader$shaded_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$shaded_q$1
module top$lanes$1$shader$shaded_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$shaded_q$2
module top$lanes$1$shader$valid_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$0
module top$lanes$1$shader$valid_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$1
module top$lanes$1$shader$valid_q$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$10
module top$lanes$1$shader$valid_q$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$11
module top$lanes$1$shader$valid_q$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$12
module top$lanes$1$shader$valid_q$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$13
module top$lanes$1$shader$valid_q$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$14
module top$lanes$1$shader$valid_q$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$15
module top$lanes$1$shader$valid_q$16(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$16
module top$lanes$1$shader$valid_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$2
module top$lanes$1$shader$valid_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$3
module top$lanes$1$shader$valid_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$4
module top$lanes$1$shader$valid_q$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$5
module top$lanes$1$shader$valid_q$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$6
module top$lanes$1$shader$valid_q$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$7
module top$lanes$1$shader$valid_q$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$8
module top$lanes$1$shader$valid_q$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q$9
module top$lanes$1$shader$value_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$0
module top$lanes$1$shader$value_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$1
module top$lanes$1$shader$value_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$10
module top$lanes$1$shader$value_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$11
module top$lanes$1$shader$value_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$12
module top$lanes$1$shader$value_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$13
module top$lanes$1$shader$value_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$14
module top$lanes$1$shader$value_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$15
module top$lanes$1$shader$value_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$2
module top$lanes$1$shader$value_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$3
module top$lanes$1$shader$value_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$4
module top$lanes$1$shader$value_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$5
module top$lanes$1$shader$value_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$6
module top$lanes$1$shader$value_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$7
module top$lanes$1$shader$value_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$8
module top$lanes$1$shader$value_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$value_q$9
module top$lanes$2$shader(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0 = 'h0;
    wire  normal$q_neg$1 = 'h0;
    wire  normal$q_neg$2 = 'h0;
    wire  [6:0] normal$q_mag$0 = 'h0;
    wire  [6:0] normal$q_mag$1 = 'h0;
    wire  [6:0] normal$q_mag$2 = 'h0;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [6:0] lighting$q_mag$0;
    reg  [6:0] lighting$q_mag$1;
    reg  [6:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse = 'h0;
    wire  [15:0] lighting$specular = 'h0;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] alpha_q$9$d;
    wire  [15:0] alpha_q$9$q;
    reg  alpha_q$9$clock;
    reg  [15:0] alpha_q$10$d;
    wire  [15:0] alpha_q$10$q;
    reg  alpha_q$10$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  [15:0] value_q$14$d;
    wire  [15:0] value_q$14$q;
    reg  value_q$14$clock;
    reg  [15:0] value_q$15$d;
    wire  [15:0] value_q$15$q;
    reg  value_q$15$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  valid_q$15$d;
    wire  valid_q$15$q;
    reg  valid_q$15$clock;
    reg  valid_q$16$d;
    wire  valid_q$16$q;
    reg  valid_q$16$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    reg  [15:0] lit_r$c;
    wire  [15:0] lit_r$y = 'h0;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    reg  [15:0] lit_g$c;
    wire  [15:0] lit_g$y = 'h0;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    reg  [15:0] lit_b$c;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    
    // Sub module instances
    top$lanes$2$shader$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$lanes$2$shader$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$lanes$2$shader$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$lanes$2$shader$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$lanes$2$shader$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$lanes$2$shader$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$lanes$2$shader$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$lanes$2$shader$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$lanes$2$shader$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$lanes$2$shader$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$lanes$2$shader$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$lanes$2$shader$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$lanes$2$shader$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$lanes$2$shader$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$lanes$2$shader$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$lanes$2$shader$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$lanes$2$shader$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$lanes$2$shader$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$lanes$2$shader$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$lanes$2$shader$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$lanes$2$shader$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$lanes$2$shader$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$lanes$2$shader$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$lanes$2$shader$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$lanes$2$shader$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$lanes$2$shader$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$lanes$2$shader$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$lanes$2$shader$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$lanes$2$shader$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$lanes$2$shader$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$lanes$2$shader$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$lanes$2$shader$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$lanes$2$shader$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$lanes$2$shader$alpha_q$9 alpha_q$9(
        .d(alpha_q$9$d),
        .q(alpha_q$9$q),
        .clock(alpha_q$9$clock)
    );
    top$lanes$2$shader$alpha_q$10 alpha_q$10(
        .d(alpha_q$10$d),
        .q(alpha_q$10$q),
        .clock(alpha_q$10$clock)
    );
    top$lanes$2$shader$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$lanes$2$shader$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$lanes$2$shader$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$lanes$2$shader$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$lanes$2$shader$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$lanes$2$shader$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$lanes$2$shader$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$lanes$2$shader$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$lanes$2$shader$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$lanes$2$shader$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$lanes$2$shader$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$lanes$2$shader$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$lanes$2$shader$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$lanes$2$shader$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$lanes$2$shader$value_q$14 value_q$14(
        .d(value_q$14$d),
        .q(value_q$14$q),
        .clock(value_q$14$clock)
    );
    top$lanes$2$shader$value_q$15 value_q$15(
        .d(value_q$15$d),
        .q(value_q$15$q),
        .clock(value_q$15$clock)
    );
    top$lanes$2$shader$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$lanes$2$shader$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$lanes$2$shader$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$lanes$2$shader$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$lanes$2$shader$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$lanes$2$shader$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$lanes$2$shader$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$lanes$2$shader$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$lanes$2$shader$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$lanes$2$shader$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$lanes$2$shader$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$lanes$2$shader$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$lanes$2$shader$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$lanes$2$shader$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$lanes$2$shader$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$lanes$2$shader$valid_q$15 valid_q$15(
        .d(valid_q$15$d),
        .q(valid_q$15$q),
        .clock(valid_q$15$clock)
    );
    top$lanes$2$shader$valid_q$16 valid_q$16(
        .d(valid_q$16$d),
        .q(valid_q$16$q),
        .clock(valid_q$16$clock)
    );
    top$lanes$2$shader$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$lanes$2$shader$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$lanes$2$shader$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$lanes$2$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$2$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$2$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$2$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        lut_q$1$clock = clock;
        lut_q$2$clock = clock;
        lut_q$3$clock = clock;
        lut_q$4$clock = clock;
        lut_q$5$clock = clock;
        lut_q$6$clock = clock;
        lut_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$0$clock = clock;
        alpha_q$1$clock = clock;
        alpha_q$2$clock = clock;
        alpha_q$3$clock = clock;
        alpha_q$4$clock = clock;
        alpha_q$5$clock = clock;
        alpha_q$6$clock = clock;
        alpha_q$7$clock = clock;
        alpha_q$8$clock = clock;
        alpha_q$9$clock = clock;
        alpha_q$10$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        value_q$14$clock = clock;
        value_q$15$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        valid_q$15$clock = clock;
        valid_q$16$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        value_q$14$d = value_q$13$q;
        value_q$15$d = value_q$14$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        valid_q$15$d = valid_q$14$q;
        valid_q$16$d = valid_q$15$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        alpha_q$9$d = alpha_q$8$q;
        alpha_q$10$d = alpha_q$9$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        lit_r$c = specular;
        lit_g$c = specular;
        lit_b$c = specular;
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = lit_r$y;
        shaded_q$1$d = lit_g$y;
        shaded_q$2$d = lit_b$y;
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$8$q;
        mul_g$b = alpha_q$8$q;
        mul_b$b = alpha_q$8$q;
        if (scalar) begin
            r_q$d = value_q$15$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$10$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$10$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$16$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$2$shader
module top$lanes$2$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$a_q
module top$lanes$2$shader$alpha_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$0
module top$lanes$2$shader$alpha_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$1
module top$lanes$2$shader$alpha_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$10
module top$lanes$2$shader$alpha_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$2
module top$lanes$2$shader$alpha_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$3
module top$lanes$2$shader$alpha_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$4
module top$lanes$2$shader$alpha_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$5
module top$lanes$2$shader$alpha_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$6
module top$lanes$2$shader$alpha_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$7
module top$lanes$2$shader$alpha_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$8
module top$lanes$2$shader$alpha_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$alpha_q$9
module top$lanes$2$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$b_q
module top$lanes$2$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$g_q
module top$lanes$2$shader$gate_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$gate_q$0
module top$lanes$2$shader$gate_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$gate_q$1
module top$lanes$2$shader$gate_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$gate_q$2
module top$lanes$2$shader$gate_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$gate_q$3
module top$lanes$2$shader$gate_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$gate_q$4
module top$lanes$2$shader$lut_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$0
module top$lanes$2$shader$lut_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$1
module top$lanes$2$shader$lut_q$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$2
module top$lanes$2$shader$lut_q$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$3
module top$lanes$2$shader$lut_q$4(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$4
module top$lanes$2$shader$lut_q$5(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$5
module top$lanes$2$shader$lut_q$6(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$6
module top$lanes$2$shader$lut_q$7(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$7
module top$lanes$2$shader$lut_q$8(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$lut_q$8
module top$lanes$2$shader$mag_in$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$mag_in$0
module top$lanes$2$shader$mag_in$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$mag_in$1
module top$lanes$2$shader$mag_in$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$mag_in$2
module top$lanes$2$shader$neg_in$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$neg_in$0
module top$lanes$2$shader$neg_in$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$neg_in$1
module top$lanes$2$shader$neg_in$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$neg_in$2
module top$lanes$2$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$r_q
module top$lanes$2$shader$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$row_q$0
module top$lanes$2$shader$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$row_q$1
module top$lanes$2$shader$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$row_q$2
module top$lanes$2$shader$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$row_q$3
module top$lanes$2$shader$shaded_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$shaded_q$0
module top$lanes$2$shader$shaded_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$shaded_q$1
module top$lanes$2$shader$shaded_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$shaded_q$2
module top$lanes$2$shader$valid_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$0
module top$lanes$2$shader$valid_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$1
module top$lanes$2$shader$valid_q$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$10
module top$lanes$2$shader$valid_q$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$11
module top$lanes$2$shader$valid_q$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$12
module top$lanes$2$shader$valid_q$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$13
module top$lanes$2$shader$valid_q$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$14
module top$lanes$2$shader$valid_q$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$15
module top$lanes$2$shader$valid_q$16(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$16
module top$lanes$2$shader$valid_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$2
module top$lanes$2$shader$valid_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$3
module top$lanes$2$shader$valid_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$4
module top$lanes$2$shader$valid_q$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$5
module top$lanes$2$shader$valid_q$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$6
module top$lanes$2$shader$valid_q$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$7
module top$lanes$2$shader$valid_q$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$8
module top$lanes$2$shader$valid_q$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q$9
module top$lanes$2$shader$value_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$0
module top$lanes$2$shader$value_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$1
module top$lanes$2$shader$value_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$10
module top$lanes$2$shader$value_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$11
module top$lanes$2$shader$value_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$12
module top$lanes$2$shader$value_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$13
module top$lanes$2$shader$value_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$14
module top$lanes$2$shader$value_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$15
module top$lanes$2$shader$value_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$2
module top$lanes$2$shader$value_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$3
module top$lanes$2$shader$value_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$4
module top$lanes$2$shader$value_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$5
module top$lanes$2$shader$value_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$6
module top$lanes$2$shader$value_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$7
module top$lanes$2$shader$value_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$8
module top$lanes$2$shader$value_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$value_q$9
module top$lanes$3$shader(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0 = 'h0;
    wire  normal$q_neg$1 = 'h0;
    wire  normal$q_neg$2 = 'h0;
    wire  [6:0] normal$q_mag$0 = 'h0;
    wire  [6:0] normal$q_mag$1 = 'h0;
    wire  [6:0] normal$q_mag$2 = 'h0;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [6:0] lighting$q_mag$0;
    reg  [6:0] lighting$q_mag$1;
    reg  [6:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse = 'h0;
    wire  [15:0] lighting$specular = 'h0;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] alpha_q$9$d;
    wire  [15:0] alpha_q$9$q;
    reg  alpha_q$9$clock;
    reg  [15:0] alpha_q$10$d;
    wire  [15:0] alpha_q$10$q;
    reg  alpha_q$10$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  [15:0] value_q$14$d;
    wire  [15:0] value_q$14$q;
    reg  value_q$14$clock;
    reg  [15:0] value_q$15$d;
    wire  [15:0] value_q$15$q;
    reg  value_q$15$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  valid_q$15$d;
    wire  valid_q$15$q;
    reg  valid_q$15$clock;
    reg  valid_q$16$d;
    wire  valid_q$16$q;
    reg  valid_q$16$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    reg  [15:0] lit_r$c;
    wire  [15:0] lit_r$y = 'h0;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    reg  [15:0] lit_g$c;
    wire  [15:0] lit_g$y = 'h0;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    reg  [15:0] lit_b$c;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    
    // Sub module instances
    top$lanes$3$shader$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$lanes$3$shader$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$lanes$3$shader$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$lanes$3$shader$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$lanes$3$shader$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$lanes$3$shader$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$lanes$3$shader$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$lanes$3$shader$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$lanes$3$shader$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$lanes$3$shader$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$lanes$3$shader$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$lanes$3$shader$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$lanes$3$shader$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$lanes$3$shader$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$lanes$3$shader$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$lanes$3$shader$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$lanes$3$shader$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$lanes$3$shader$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$lanes$3$shader$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$lanes$3$shader$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$lanes$3$shader$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$lanes$3$shader$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$lanes$3$shader$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$lanes$3$shader$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$lanes$3$shader$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$lanes$3$shader$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$lanes$3$shader$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$lanes$3$shader$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$lanes$3$shader$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$lanes$3$shader$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$lanes$3$shader$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$lanes$3$shader$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$lanes$3$shader$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$lanes$3$shader$alpha_q$9 alpha_q$9(
        .d(alpha_q$9$d),
        .q(alpha_q$9$q),
        .clock(alpha_q$9$clock)
    );
    top$lanes$3$shader$alpha_q$10 alpha_q$10(
        .d(alpha_q$10$d),
        .q(alpha_q$10$q),
        .clock(alpha_q$10$clock)
    );
    top$lanes$3$shader$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$lanes$3$shader$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$lanes$3$shader$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$lanes$3$shader$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$lanes$3$shader$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$lanes$3$shader$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$lanes$3$shader$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$lanes$3$shader$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$lanes$3$shader$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$lanes$3$shader$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$lanes$3$shader$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$lanes$3$shader$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$lanes$3$shader$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$lanes$3$shader$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$lanes$3$shader$value_q$14 value_q$14(
        .d(value_q$14$d),
        .q(value_q$14$q),
        .clock(value_q$14$clock)
    );
    top$lanes$3$shader$value_q$15 value_q$15(
        .d(value_q$15$d),
        .q(value_q$15$q),
        .clock(value_q$15$clock)
    );
    top$lanes$3$shader$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$lanes$3$shader$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$lanes$3$shader$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$lanes$3$shader$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$lanes$3$shader$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$lanes$3$shader$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$lanes$3$shader$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$lanes$3$shader$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$lanes$3$shader$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$lanes$3$shader$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$lanes$3$shader$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$lanes$3$shader$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$lanes$3$shader$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$lanes$3$shader$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$lanes$3$shader$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$lanes$3$shader$valid_q$15 valid_q$15(
        .d(valid_q$15$d),
        .q(valid_q$15$q),
        .clock(valid_q$15$clock)
    );
    top$lanes$3$shader$valid_q$16 valid_q$16(
        .d(valid_q$16$d),
        .q(valid_q$16$q),
        .clock(valid_q$16$clock)
    );
    top$lanes$3$shader$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$lanes$3$shader$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$lanes$3$shader$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$lanes$3$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$3$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$3$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$3$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        lut_q$1$clock = clock;
        lut_q$2$clock = clock;
        lut_q$3$clock = clock;
        lut_q$4$clock = clock;
        lut_q$5$clock = clock;
        lut_q$6$clock = clock;
        lut_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$0$clock = clock;
        alpha_q$1$clock = clock;
        alpha_q$2$clock = clock;
        alpha_q$3$clock = clock;
        alpha_q$4$clock = clock;
        alpha_q$5$clock = clock;
        alpha_q$6$clock = clock;
        alpha_q$7$clock = clock;
        alpha_q$8$clock = clock;
        alpha_q$9$clock = clock;
        alpha_q$10$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        value_q$14$clock = clock;
        value_q$15$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        valid_q$15$clock = clock;
        valid_q$16$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        value_q$14$d = value_q$13$q;
        value_q$15$d = value_q$14$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        valid_q$15$d = valid_q$14$q;
        valid_q$16$d = valid_q$15$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        alpha_q$9$d = alpha_q$8$q;
        alpha_q$10$d = alpha_q$9$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        lit_r$c = specular;
        lit_g$c = specular;
        lit_b$c = specular;
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = lit_r$y;
        shaded_q$1$d = lit_g$y;
        shaded_q$2$d = lit_b$y;
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$8$q;
        mul_g$b = alpha_q$8$q;
        mul_b$b = alpha_q$8$q;
        if (scalar) begin
            r_q$d = value_q$15$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$10$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$10$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$16$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$3$shader
module top$lanes$3$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$a_q
module top$lanes$3$shader$alpha_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$0
module top$lanes$3$shader$alpha_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$1
module top$lanes$3$shader$alpha_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$10
module top$lanes$3$shader$alpha_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$2
module top$lanes$3$shader$alpha_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$3
module top$lanes$3$shader$alpha_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$4
module top$lanes$3$shader$alpha_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$5
module top$lanes$3$shader$alpha_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$6
module top$lanes$3$shader$alpha_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$7
module top$lanes$3$shader$alpha_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$8
module top$lanes$3$shader$alpha_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$alpha_q$9
module top$lanes$3$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$b_q
module top$lanes$3$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$g_q
module top$lanes$3$shader$gate_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$gate_q$0
module top$lanes$3$shader$gate_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$gate_q$1
module top$lanes$3$shader$gate_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$gate_q$2
module top$lanes$3$shader$gate_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$gate_q$3
module top$lanes$3$shader$gate_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$gate_q$4
module top$lanes$3$shader$lut_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$0
module top$lanes$3$shader$lut_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$1
module top$lanes$3$shader$lut_q$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$2
module top$lanes$3$shader$lut_q$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$3
module top$lanes$3$shader$lut_q$4(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$4
module top$lanes$3$shader$lut_q$5(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$5
module top$lanes$3$shader$lut_q$6(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$6
module top$lanes$3$shader$lut_q$7(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$7
module top$lanes$3$shader$lut_q$8(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$lut_q$8
module top$lanes$3$shader$mag_in$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$mag_in$0
module top$lanes$3$shader$mag_in$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$mag_in$1
module top$lanes$3$shader$mag_in$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$mag_in$2
module top$lanes$3$shader$neg_in$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$neg_in$0
module top$lanes$3$shader$neg_in$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$neg_in$1
module top$lanes$3$shader$neg_in$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$neg_in$2
module top$lanes$3$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$r_q
module top$lanes$3$shader$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$row_q$0
module top$lanes$3$shader$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$row_q$1
module top$lanes$3$shader$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$row_q$2
module top$lanes$3$shader$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$row_q$3
module top$lanes$3$shader$shaded_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$shaded_q$0
module top$lanes$3$shader$shaded_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$shaded_q$1
module top$lanes$3$shader$shaded_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$shaded_q$2
module top$lanes$3$shader$valid_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$0
module top$lanes$3$shader$valid_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$1
module top$lanes$3$shader$valid_q$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$10
module top$lanes$3$shader$valid_q$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$11
module top$lanes$3$shader$valid_q$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$12
module top$lanes$3$shader$valid_q$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$13
module top$lanes$3$shader$valid_q$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$14
module top$lanes$3$shader$valid_q$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$15
module top$lanes$3$shader$valid_q$16(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$16
module top$lanes$3$shader$valid_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$2
module top$lanes$3$shader$valid_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$3
module top$lanes$3$shader$valid_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$4
module top$lanes$3$shader$valid_q$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$5
module top$lanes$3$shader$valid_q$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$6
module top$lanes$3$shader$valid_q$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$7
module top$lanes$3$shader$valid_q$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$8
module top$lanes$3$shader$valid_q$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q$9
module top$lanes$3$shader$value_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$0
module top$lanes$3$shader$value_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$1
module top$lanes$3$shader$value_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$10
module top$lanes$3$shader$value_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$11
module top$lanes$3$shader$value_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$12
module top$lanes$3$shader$value_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$13
module top$lanes$3$shader$value_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$14
module top$lanes$3$shader$value_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$15
module top$lanes$3$shader$value_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$2
module top$lanes$3$shader$value_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$3
module top$lanes$3$shader$value_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$4
module top$lanes$3$shader$value_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$5
module top$lanes$3$shader$value_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$6
module top$lanes$3$shader$value_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$7
module top$lanes$3$shader$value_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$8
module top$lanes$3$shader$value_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$value_q$9
