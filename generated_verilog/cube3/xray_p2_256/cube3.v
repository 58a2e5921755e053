module top$pipeline(clock,host_write,host_address,host_data,start,valid,cur$0,cur$1,next$0,next$1,done,pixel_r,pixel_g,pixel_b,pixel_a,has_sample);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  start;
    input wire  valid;
    input wire  [15:0] cur$0;
    input wire  [15:0] cur$1;
    input wire  [15:0] next$0;
    input wire  [15:0] next$1;
    output reg  done;
    output reg  [31:0] pixel_r;
    output reg  [15:0] pixel_g;
    output reg  [15:0] pixel_b;
    output reg  [15:0] pixel_a;
    output reg  has_sample;
    
    // Constant declarations
    localparam  flags_last = 16'h0;
    localparam  cast_bit = 8'h4;
    localparam  gradients = 1'b0;
    localparam  shaded = 1'b0;
    localparam  xray = 1'b1;
    localparam  half = 'h8;
    localparam  frac = 8'h4;
    localparam  row_shift = 8'h0;
    localparam  lane_bit$0 = 'h1;
    localparam  lane_bit$1 = 'h2;
    localparam  lane_bit$2 = 'h4;
    localparam  lane_bit$3 = 'h8;
    localparam  lane_bit$4 = 'h10;
    localparam  lane_bit$5 = 'h20;
    localparam  lane_bit$6 = 'h40;
    localparam  lane_bit$7 = 'h80;
    localparam  inner_bit$0 = 'h10000;
    localparam  inner_bit$1 = 'h20000;
    localparam  inner_bit$2 = 'h40000;
    localparam  inner_bit$3 = 'h80000;
    localparam  inner_bit$4 = 'h100000;
    localparam  inner_bit$5 = 'h200000;
    localparam  inner_bit$6 = 'h400000;
    localparam  inner_bit$7 = 'h800000;
    
    // Stub signals
    reg  control$clock;
    reg  control$start;
    reg  control$valid;
    wire  control$first;
    wire  control$unit_valid;
    wire  control$unit_first;
    wire  control$unit_last;
    wire  control$unit_cast;
    wire  [15:0] control$wx$0;
    wire  [15:0] control$wx$1;
    wire  [15:0] control$wy$0;
    wire  [15:0] control$wy$1;
    wire  [7:0] control$in_volume;
    wire  [7:0] control$in_inner;
    wire  control$dx_neg;
    wire  [15:0] control$dx_mag;
    wire  control$dy_neg;
    wire  [15:0] control$dy_mag;
    reg  lanes$clock;
    reg  [15:0] lanes$cur$0;
    reg  [15:0] lanes$cur$1;
    reg  [15:0] lanes$next$0;
    reg  [15:0] lanes$next$1;
    reg  lanes$first;
    reg  [15:0] lanes$wx$0;
    reg  [15:0] lanes$wx$1;
    reg  [15:0] lanes$wy$0;
    reg  [15:0] lanes$wy$1;
    wire  [31:0] lanes$sample$0;
    wire  [31:0] lanes$sample$1;
    reg  [31:0] flags_q$0$d;
    wire  [31:0] flags_q$0$q;
    reg  flags_q$0$clock;
    reg  [31:0] flags_q$1$d;
    wire  [31:0] flags_q$1$q;
    reg  flags_q$1$clock;
    reg  [31:0] flags_q$2$d;
    wire  [31:0] flags_q$2$q;
    reg  flags_q$2$clock;
    reg  [31:0] flags_q$3$d;
    wire  [31:0] flags_q$3$q;
    reg  flags_q$3$clock;
    reg  [31:0] flags_q$4$d;
    wire  [31:0] flags_q$4$q;
    reg  flags_q$4$clock;
    reg  [31:0] flags_q$5$d;
    wire  [31:0] flags_q$5$q;
    reg  flags_q$5$clock;
    reg  [31:0] flags_q$6$d;
    wire  [31:0] flags_q$6$q;
    reg  flags_q$6$clock;
    reg  flags_line$clock;
    reg  [31:0] flags_line$data_in;
    reg  flags_line$write_enable;
    wire  [31:0] flags_line$data_out;
    reg  [15:0] flags_line$last;
    reg  [31:0] shade_flags_q$0$d;
    wire  [31:0] shade_flags_q$0$q;
    reg  shade_flags_q$0$clock;
    reg  [31:0] shade_flags_q$1$d;
    wire  [31:0] shade_flags_q$1$q;
    reg  shade_flags_q$1$clock;
    reg  [31:0] shade_flags_q$2$d;
    wire  [31:0] shade_flags_q$2$q;
    reg  shade_flags_q$2$clock;
    reg  [31:0] shade_flags_q$3$d;
    wire  [31:0] shade_flags_q$3$q;
    reg  shade_flags_q$3$clock;
    reg  [31:0] shade_flags_q$4$d;
    wire  [31:0] shade_flags_q$4$q;
    reg  shade_flags_q$4$clock;
    reg  [31:0] shade_flags_q$5$d;
    wire  [31:0] shade_flags_q$5$q;
    reg  shade_flags_q$5$clock;
    reg  [31:0] rpc_flags_q$d;
    wire  [31:0] rpc_flags_q$q;
    reg  rpc_flags_q$clock;
    reg  [7:0] cast_q$d;
    wire  [7:0] cast_q$q;
    reg  cast_q$clock;
    reg  [11:0] opacity$0$address;
    wire  [31:0] opacity$0$data;
    reg  [11:0] opacity$1$address;
    wire  [31:0] opacity$1$data;
    reg  [31:0] leaf_q$0$d;
    wire  [31:0] leaf_q$0$q;
    reg  leaf_q$0$clock;
    reg  [31:0] leaf_q$1$d;
    wire  [31:0] leaf_q$1$q;
    reg  leaf_q$1$clock;
    reg  leaf_valid_q$0$d;
    wire  leaf_valid_q$0$q;
    reg  leaf_valid_q$0$clock;
    reg  leaf_valid_q$1$d;
    wire  leaf_valid_q$1$q;
    reg  leaf_valid_q$1$clock;
    reg  abc$clock;
    reg  [31:0] abc$sample$0;
    reg  [31:0] abc$sample$1;
    reg  abc$dx_neg;
    reg  [15:0] abc$dx_mag;
    reg  abc$dy_neg;
    reg  [15:0] abc$dy_mag;
    wire  [31:0] abc$centre$0 = 'h0;
    wire  [31:0] abc$centre$1 = 'h0;
    wire  [31:0] abc$gx$0 = 'h0;
    wire  [31:0] abc$gx$1 = 'h0;
    wire  [31:0] abc$gy$0 = 'h0;
    wire  [31:0] abc$gy$1 = 'h0;
    wire  [31:0] abc$gz$0 = 'h0;
    wire  [31:0] abc$gz$1 = 'h0;
    reg  shade$0$clock;
    reg  shade$0$host_write;
    reg  [23:0] shade$0$host_address;
    reg  [63:0] shade$0$host_data;
    reg  [15:0] shade$0$value;
    reg  shade$0$invalid;
    reg  shade$0$at_edge;
    reg  shade$0$gx_neg;
    reg  [31:0] shade$0$gx_mag;
    reg  shade$0$gy_neg;
    reg  [31:0] shade$0$gy_mag;
    reg  shade$0$gz_neg;
    reg  [31:0] shade$0$gz_mag;
    wire  [31:0] shade$0$r = 'h0;
    wire  [15:0] shade$0$g = 'h0;
    wire  [15:0] shade$0$b = 'h0;
    wire  [15:0] shade$0$a = 'h0;
    wire  shade$0$valid = 'h0;
    reg  shade$1$clock;
    reg  shade$1$host_write;
    reg  [23:0] shade$1$host_address;
    reg  [63:0] shade$1$host_data;
    reg  [15:0] shade$1$value;
    reg  shade$1$invalid;
    reg  shade$1$at_edge;
    reg  shade$1$gx_neg;
    reg  [31:0] shade$1$gx_mag;
    reg  shade$1$gy_neg;
    reg  [31:0] shade$1$gy_mag;
    reg  shade$1$gz_neg;
    reg  [31:0] shade$1$gz_mag;
    wire  [31:0] shade$1$r = 'h0;
    wire  [15:0] shade$1$g = 'h0;
    wire  [15:0] shade$1$b = 'h0;
    wire  [15:0] shade$1$a = 'h0;
    wire  shade$1$valid = 'h0;
    reg  rpc$clock;
    reg  [31:0] rpc$leaf_r$0;
    reg  [31:0] rpc$leaf_r$1;
    reg  [15:0] rpc$leaf_g$0;
    reg  [15:0] rpc$leaf_g$1;
    reg  [15:0] rpc$leaf_b$0;
    reg  [15:0] rpc$leaf_b$1;
    reg  [15:0] rpc$leaf_a$0;
    reg  [15:0] rpc$leaf_a$1;
    reg  rpc$leaf_valid$0;
    reg  rpc$leaf_valid$1;
    reg  rpc$first;
    reg  rpc$last;
    wire  rpc$done;
    wire  [31:0] rpc$pixel_r;
    wire  [15:0] rpc$pixel_g;
    wire  [15:0] rpc$pixel_b;
    wire  [15:0] rpc$pixel_a;
    wire  rpc$has_sample;
    
    // Local signals
    reg  [31:0] leaf_flags;
    reg  pixel_cast;
    reg  [31:0] row$0;
    reg  [31:0] row$1;
    reg  [31:0] index$0;
    reg  [31:0] index$1;
    reg  [31:0] gx$0;
    reg  [31:0] gx$1;
    reg  [31:0] gy$0;
    reg  [31:0] gy$1;
    reg  [31:0] gz$0;
    reg  [31:0] gz$1;
    
    // Sub module instances
    top$pipeline$control control(
        .clock(control$clock),
        .start(control$start),
        .valid(control$valid),
        .first(control$first),
        .unit_valid(control$unit_valid),
        .unit_first(control$unit_first),
        .unit_last(control$unit_last),
        .unit_cast(control$unit_cast),
        .wx$0(control$wx$0),
        .wx$1(control$wx$1),
        .wy$0(control$wy$0),
        .wy$1(control$wy$1),
        .in_volume(control$in_volume),
        .in_inner(control$in_inner),
        .dx_neg(control$dx_neg),
        .dx_mag(control$dx_mag),
        .dy_neg(control$dy_neg),
        .dy_mag(control$dy_mag)
    );
    top$pipeline$lanes lanes(
        .clock(lanes$clock),
        .cur$0(lanes$cur$0),
        .cur$1(lanes$cur$1),
        .next$0(lanes$next$0),
        .next$1(lanes$next$1),
        .first(lanes$first),
        .wx$0(lanes$wx$0),
        .wx$1(lanes$wx$1),
        .wy$0(lanes$wy$0),
        .wy$1(lanes$wy$1),
        .sample$0(lanes$sample$0),
        .sample$1(lanes$sample$1)
    );
    top$pipeline$flags_q$0 flags_q$0(
        .d(flags_q$0$d),
        .q(flags_q$0$q),
        .clock(flags_q$0$clock)
    );
    top$pipeline$flags_q$1 flags_q$1(
        .d(flags_q$1$d),
        .q(flags_q$1$q),
        .clock(flags_q$1$clock)
    );
    top$pipeline$flags_q$2 flags_q$2(
        .d(flags_q$2$d),
        .q(flags_q$2$q),
        .clock(flags_q$2$clock)
    );
    top$pipeline$flags_q$3 flags_q$3(
        .d(flags_q$3$d),
        .q(flags_q$3$q),
        .clock(flags_q$3$clock)
    );
    top$pipeline$flags_q$4 flags_q$4(
        .d(flags_q$4$d),
        .q(flags_q$4$q),
        .clock(flags_q$4$clock)
    );
    top$pipeline$flags_q$5 flags_q$5(
        .d(flags_q$5$d),
        .q(flags_q$5$q),
        .clock(flags_q$5$clock)
    );
    top$pipeline$flags_q$6 flags_q$6(
        .d(flags_q$6$d),
        .q(flags_q$6$q),
        .clock(flags_q$6$clock)
    );
    top$pipeline$flags_line flags_line(
        .clock(flags_line$clock),
        .data_in(flags_line$data_in),
        .write_enable(flags_line$write_enable),
        .data_out(flags_line$data_out),
        .last(flags_line$last)
    );
    top$pipeline$shade_flags_q$0 shade_flags_q$0(
        .d(shade_flags_q$0$d),
        .q(shade_flags_q$0$q),
        .clock(shade_flags_q$0$clock)
    );
    top$pipeline$shade_flags_q$1 shade_flags_q$1(
        .d(shade_flags_q$1$d),
        .q(shade_flags_q$1$q),
        .clock(shade_flags_q$1$clock)
    );
    top$pipeline$shade_flags_q$2 shade_flags_q$2(
        .d(shade_flags_q$2$d),
        .q(shade_flags_q$2$q),
        .clock(shade_flags_q$2$clock)
    );
    top$pipeline$shade_flags_q$3 shade_flags_q$3(
        .d(shade_flags_q$3$d),
        .q(shade_flags_q$3$q),
        .clock(shade_flags_q$3$clock)
    );
    top$pipeline$shade_flags_q$4 shade_flags_q$4(
        .d(shade_flags_q$4$d),
        .q(shade_flags_q$4$q),
        .clock(shade_flags_q$4$clock)
    );
    top$pipeline$shade_flags_q$5 shade_flags_q$5(
        .d(shade_flags_q$5$d),
        .q(shade_flags_q$5$q),
        .clock(shade_flags_q$5$clock)
    );
    top$pipeline$rpc_flags_q rpc_flags_q(
        .d(rpc_flags_q$d),
        .q(rpc_flags_q$q),
        .clock(rpc_flags_q$clock)
    );
    top$pipeline$cast_q cast_q(
        .d(cast_q$d),
        .q(cast_q$q),
        .clock(cast_q$clock)
    );
    top$pipeline$opacity$0 opacity$0(
        .address(opacity$0$address),
        .data(opacity$0$data)
    );
    top$pipeline$opacity$1 opacity$1(
        .address(opacity$1$address),
        .data(opacity$1$data)
    );
    top$pipeline$leaf_q$0 leaf_q$0(
        .d(leaf_q$0$d),
        .q(leaf_q$0$q),
        .clock(leaf_q$0$clock)
    );
    top$pipeline$leaf_q$1 leaf_q$1(
        .d(leaf_q$1$d),
        .q(leaf_q$1$q),
        .clock(leaf_q$1$clock)
    );
    top$pipeline$leaf_valid_q$0 leaf_valid_q$0(
        .d(leaf_valid_q$0$d),
        .q(leaf_valid_q$0$q),
        .clock(leaf_valid_q$0$clock)
    );
    top$pipeline$leaf_valid_q$1 leaf_valid_q$1(
        .d(leaf_valid_q$1$d),
        .q(leaf_valid_q$1$q),
        .clock(leaf_valid_q$1$clock)
    );
    top$pipeline$rpc rpc(
        .clock(rpc$clock),
        .leaf_r$0(rpc$leaf_r$0),
        .leaf_r$1(rpc$leaf_r$1),
        .leaf_g$0(rpc$leaf_g$0),
        .leaf_g$1(rpc$leaf_g$1),
        .leaf_b$0(rpc$leaf_b$0),
        .leaf_b$1(rpc$leaf_b$1),
        .leaf_a$0(rpc$leaf_a$0),
        .leaf_a$1(rpc$leaf_a$1),
        .leaf_valid$0(rpc$leaf_valid$0),
        .leaf_valid$1(rpc$leaf_valid$1),
        .first(rpc$first),
        .last(rpc$last),
        .done(rpc$done),
        .pixel_r(rpc$pixel_r),
        .pixel_g(rpc$pixel_g),
        .pixel_b(rpc$pixel_b),
        .pixel_a(rpc$pixel_a),
        .has_sample(rpc$has_sample)
    );
    
    // Update code
    reg  [31:0] pixel_r_pass;
    reg  [15:0] pixel_g_pass;
    reg  [15:0] pixel_b_pass;
    reg  [15:0] pixel_a_pass;
    reg  has_sample_pass;
    always @(*) begin
        control$clock = clock;
        lanes$clock = clock;
        abc$clock = clock;
        rpc$clock = clock;
        flags_line$clock = clock;
        flags_line$last = flags_last;
        rpc_flags_q$clock = clock;
        cast_q$clock = clock;
        control$start = start;
        control$valid = valid;
        lanes$first = control$first;
        flags_q$0$clock = clock;
        flags_q$1$clock = clock;
        flags_q$2$clock = clock;
        flags_q$3$clock = clock;
        flags_q$4$clock = clock;
        flags_q$5$clock = clock;
        flags_q$6$clock = clock;
        flags_q$0$d = 32'(control$in_volume) | (32'(control$unit_valid) << 'h8) | (32'(control$unit_first) << 'h9) | (32'(control$unit_last) << 'ha) | (32'(control$unit_cast) << 'hb) | (32'(control$in_inner) << 'h10);
        flags_q$1$d = flags_q$0$q;
        flags_q$2$d = flags_q$1$q;
        flags_q$3$d = flags_q$2$q;
        flags_q$4$d = flags_q$3$q;
        flags_q$5$d = flags_q$4$q;
        flags_q$6$d = flags_q$5$q;
        flags_line$write_enable = 1'b1;
        flags_line$data_in = flags_q$6$q;
        leaf_flags = flags_q$6$q;
        if (gradients) begin
            leaf_flags = flags_line$data_out;
        end
        shade_flags_q$0$clock = clock;
        shade_flags_q$1$clock = clock;
        shade_flags_q$2$clock = clock;
        shade_flags_q$3$clock = clock;
        shade_flags_q$4$clock = clock;
        shade_flags_q$5$clock = clock;
        shade_flags_q$0$d = leaf_flags;
        shade_flags_q$1$d = shade_flags_q$0$q;
        shade_flags_q$2$d = shade_flags_q$1$q;
        shade_flags_q$3$d = shade_flags_q$2$q;
        shade_flags_q$4$d = shade_flags_q$3$q;
        shade_flags_q$5$d = shade_flags_q$4$q;
        rpc_flags_q$d = leaf_flags;
        if (shaded) begin
            rpc_flags_q$d = shade_flags_q$5$q;
        end
        abc$dx_neg = control$dx_neg;
        abc$dx_mag = control$dx_mag;
        abc$dy_neg = control$dy_neg;
        abc$dy_mag = control$dy_mag;
        lanes$cur$0 = cur$0;
        lanes$next$0 = next$0;
        lanes$wx$0 = control$wx$0;
        lanes$wy$0 = control$wy$0;
        abc$sample$0 = lanes$sample$0;
        leaf_q$0$clock = clock;
        leaf_valid_q$0$clock = clock;
        row$0 = (lanes$sample$0 >> frac) >> row_shift;
        opacity$0$address = row$0[('h0)+:(12)];
        leaf_valid_q$0$d = |(flags_q$6$q & lane_bit$0);
        leaf_q$0$d = 'h0;
        if (|(flags_q$6$q & lane_bit$0)) begin
            leaf_q$0$d = (lanes$sample$0 + half) >> frac;
            if (xray) begin
                leaf_q$0$d = opacity$0$data;
            end
        end
        index$0 = lanes$sample$0 >> frac;
        gx$0 = 'h0;
        gy$0 = 'h0;
        gz$0 = 'h0;
        if (gradients) begin
            index$0 = abc$centre$0 >> frac;
            gx$0 = abc$gx$0;
            gy$0 = abc$gy$0;
            gz$0 = abc$gz$0;
        end
        shade$0$clock = clock;
        shade$0$host_write = host_write;
        shade$0$host_address = host_address;
        shade$0$host_data = host_data;
        shade$0$value = index$0[('h0)+:(16)];
        shade$0$invalid = ~|(leaf_flags & lane_bit$0);
        shade$0$at_edge = ~|(leaf_flags & inner_bit$0);
        shade$0$gx_neg = gx$0['h1f];
        shade$0$gx_mag = gx$0;
        if (gx$0['h1f]) begin
            shade$0$gx_mag = ~gx$0 + 'h1;
        end
        shade$0$gy_neg = gy$0['h1f];
        shade$0$gy_mag = gy$0;
        if (gy$0['h1f]) begin
            shade$0$gy_mag = ~gy$0 + 'h1;
        end
        shade$0$gz_neg = gz$0['h1f];
        shade$0$gz_mag = gz$0;
        if (gz$0['h1f]) begin
            shade$0$gz_mag = ~gz$0 + 'h1;
        end
        rpc$leaf_r$0 = leaf_q$0$q;
        rpc$leaf_g$0 = 'h0;
        rpc$leaf_b$0 = 'h0;
        rpc$leaf_a$0 = 'h0;
        rpc$leaf_valid$0 = leaf_valid_q$0$q;
        if (shaded) begin
            rpc$leaf_r$0 = shade$0$r;
            rpc$leaf_g$0 = shade$0$g;
            rpc$leaf_b$0 = shade$0$b;
            rpc$leaf_a$0 = shade$0$a;
            rpc$leaf_valid$0 = shade$0$valid;
        end
        lanes$cur$1 = cur$1;
        lanes$next$1 = next$1;
        lanes$wx$1 = control$wx$1;
        lanes$wy$1 = control$wy$1;
        abc$sample$1 = lanes$sample$1;
        leaf_q$1$clock = clock;
        leaf_valid_q$1$clock = clock;
        row$1 = (lanes$sample$1 >> frac) >> row_shift;
        opacity$1$address = row$1[('h0)+:(12)];
        leaf_valid_q$1$d = |(flags_q$6$q & lane_bit$1);
        leaf_q$1$d = 'h0;
        if (|(flags_q$6$q & lane_bit$1)) begin
            leaf_q$1$d = (lanes$sample$1 + half) >> frac;
            if (xray) begin
                leaf_q$1$d = opacity$1$data;
            end
        end
        index$1 = lanes$sample$1 >> frac;
        gx$1 = 'h0;
        gy$1 = 'h0;
        gz$1 = 'h0;
        if (gradients) begin
            index$1 = abc$centre$1 >> frac;
            gx$1 = abc$gx$1;
            gy$1 = abc$gy$1;
            gz$1 = abc$gz$1;
        end
        shade$1$clock = clock;
        shade$1$host_write = host_write;
        shade$1$host_address = host_address;
        shade$1$host_data = host_data;
        shade$1$value = index$1[('h0)+:(16)];
        shade$1$invalid = ~|(leaf_flags & lane_bit$1);
        shade$1$at_edge = ~|(leaf_flags & inner_bit$1);
        shade$1$gx_neg = gx$1['h1f];
        shade$1$gx_mag = gx$1;
        if (gx$1['h1f]) begin
            shade$1$gx_mag = ~gx$1 + 'h1;
        end
        shade$1$gy_neg = gy$1['h1f];
        shade$1$gy_mag = gy$1;
        if (gy$1['h1f]) begin
            shade$1$gy_mag = ~gy$1 + 'h1;
        end
        shade$1$gz_neg = gz$1['h1f];
        shade$1$gz_mag = gz$1;
        if (gz$1['h1f]) begin
            shade$1$gz_mag = ~gz$1 + 'h1;
        end
        rpc$leaf_r$1 = leaf_q$1$q;
        rpc$leaf_g$1 = 'h0;
        rpc$leaf_b$1 = 'h0;
        rpc$leaf_a$1 = 'h0;
        rpc$leaf_valid$1 = leaf_valid_q$1$q;
        if (shaded) begin
            rpc$leaf_r$1 = shade$1$r;
            rpc$leaf_g$1 = shade$1$g;
            rpc$leaf_b$1 = shade$1$b;
            rpc$leaf_a$1 = shade$1$a;
            rpc$leaf_valid$1 = shade$1$valid;
        end
        rpc$first = rpc_flags_q$q['h9] & rpc_flags_q$q['h8];
        rpc$last = rpc_flags_q$q['ha] & rpc_flags_q$q['h8];
        cast_q$d = (cast_q$q << 'h1) | 8'(rpc_flags_q$q['hb]);
        pixel_cast = |(cast_q$q & cast_bit);
        done = rpc$done;
        pixel_r_pass = 'h0;
        pixel_g_pass = 'h0;
        pixel_b_pass = 'h0;
        pixel_a_pass = 'h0;
        has_sample_pass = 1'b0;
        if (pixel_cast) begin
            pixel_r_pass = rpc$pixel_r;
            pixel_g_pass = rpc$pixel_g;
            pixel_b_pass = rpc$pixel_b;
            pixel_a_pass = rpc$pixel_a;
            has_sample_pass = rpc$has_sample;
        end
        pixel_r = pixel_r_pass;
        pixel_g = pixel_g_pass;
        pixel_b = pixel_b_pass;
        pixel_a = pixel_a_pass;
        has_sample = has_sample_pass;
    end
    
endmodule // top$pipeline
module top$pipeline$cast_q(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$cast_q
module top$pipeline$flags_line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h1;
    localparam  single = 1'b1;
    localparam  mask = 'hff0fff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$flags_line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$flags_line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$flags_line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        next = ptr$q + 'h1;
        if ((ptr$q >= last) | (ptr$q >= longest_last)) begin
            next = 'h0;
        end
        ptr$d = next;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = next;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$flags_line
module top$pipeline$flags_line$one(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_line$one
module top$pipeline$flags_line$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_line$ptr
module top$pipeline$flags_line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [19:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[0:0]][19:12], 4'd0, mem[read_address[0:0]][11:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[23:16], write_data[11:0]};
       end
    end
endmodule // top$pipeline$flags_line$ram
module top$pipeline$flags_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$0
module top$pipeline$flags_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$1
module top$pipeline$flags_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$2
module top$pipeline$flags_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$3
module top$pipeline$flags_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$4
module top$pipeline$flags_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$5
module top$pipeline$flags_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$6
module top$pipeline$leaf_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_q$0
module top$pipeline$leaf_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_q$1
module top$pipeline$leaf_valid_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_valid_q$0
module top$pipeline$leaf_valid_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_valid_q$1
module top$pipeline$opacity$0(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 'h0;
      12'h1: data = 'h0;
      12'h2: data = 'h0;
      12'h3: data = 'h0;
      12'h4: data = 'h0;
      12'h5: data = 'h0;
      12'h6: data = 'h0;
      12'h7: data = 'h0;
      12'h8: data = 'h0;
      12'h9: data = 'h0;
      12'ha: data = 'h0;
      12'hb: data = 'h0;
      12'hc: data = 'h0;
      12'hd: data = 'h0;
      12'he: data = 'h0;
      12'hf: data = 'h0;
      12'h10: data = 'h0;
      12'h11: data = 'h0;
      12'h12: data = 'h0;
      12'h13: data = 'h0;
      12'h14: data = 'h0;
      12'h15: data = 'h0;
      12'h16: data = 'h0;
      12'h17: data = 'h0;
      12'h18: data = 'h0;
      12'h19: data = 'h0;
      12'h1a: data = 'h0;
      12'h1b: data = 'h0;
      12'h1c: data = 'h0;
      12'h1d: data = 'h0;
      12'h1e: data = 'h0;
      12'h1f: data = 'h0;
      12'h20: data = 'h0;
      12'h21: data = 'h0;
      12'h22: data = 'h0;
      12'h23: data = 'h0;
      12'h24: data = 'h0;
      12'h25: data = 'h0;
      12'h26: data = 'h0;
      12'h27: data = 'h0;
      12'h28: data = 'h0;
      12'h29: data = 'h0;
      12'h2a: data = 'h0;
      12'h2b: data = 'h0;
      12'h2c: data = 'h0;
      12'h2d: data = 'h0;
      12'h2e: data = 'h0;
      12'h2f: data = 'h0;
      12'h30: data = 'h0;
      12'h31: data = 'h0;
      12'h32: data = 'h0;
      12'h33: data = 'h0;
      12'h34: data = 'h0;
      12'h35: data = 'h0;
      12'h36: data = 'h0;
      12'h37: data = 'h0;
      12'h38: data = 'h0;
      12'h39: data = 'h0;
      12'h3a: data = 'h0;
      12'h3b: data = 'h0;
      12'h3c: data = 'h0;
      12'h3d: data = 'h0;
      12'h3e: data = 'h0;
      12'h3f: data = 'h0;
      12'h40: data = 'h0;
      12'h41: data = 'h0;
      12'h42: data = 'h0;
      12'h43: data = 'h0;
      12'h44: data = 'h0;
      12'h45: data = 'h0;
      12'h46: data = 'h0;
      12'h47: data = 'h0;
      12'h48: data = 'h0;
      12'h49: data = 'h0;
      12'h4a: data = 'h0;
      12'h4b: data = 'h0;
      12'h4c: data = 'h0;
      12'h4d: data = 'h0;
      12'h4e: data = 'h0;
      12'h4f: data = 'h0;
      12'h50: data = 'h0;
      12'h51: data = 'ha;
      12'h52: data = 'h13;
      12'h53: data = 'h1d;
      12'h54: data = 'h26;
      12'h55: data = 'h30;
      12'h56: data = 'h39;
      12'h57: data = 'h43;
      12'h58: data = 'h4d;
      12'h59: data = 'h56;
      12'h5a: data = 'h60;
      12'h5b: data = 'h69;
      12'h5c: data = 'h73;
      12'h5d: data = 'h7c;
      12'h5e: data = 'h86;
      12'h5f: data = 'h8f;
      12'h60: data = 'h99;
      12'h61: data = 'ha3;
      12'h62: data = 'hac;
      12'h63: data = 'hb6;
      12'h64: data = 'hbf;
      12'h65: data = 'hbf;
      12'h66: data = 'hbf;
      12'h67: data = 'hbf;
      12'h68: data = 'hbf;
      12'h69: data = 'hbf;
      12'h6a: data = 'hbf;
      12'h6b: data = 'hbf;
      12'h6c: data = 'hbf;
      12'h6d: data = 'hbf;
      12'h6e: data = 'hbf;
      12'h6f: data = 'hbf;
      12'h70: data = 'hbf;
      12'h71: data = 'hbf;
      12'h72: data = 'hbf;
      12'h73: data = 'hbf;
      12'h74: data = 'hbf;
      12'h75: data = 'hbf;
      12'h76: data = 'hbf;
      12'h77: data = 'hbf;
      12'h78: data = 'hbf;
      12'h79: data = 'hbf;
      12'h7a: data = 'hbf;
      12'h7b: data = 'hbf;
      12'h7c: data = 'hbf;
      12'h7d: data = 'hbf;
      12'h7e: data = 'hbf;
      12'h7f: data = 'hbf;
      12'h80: data = 'hbf;
      12'h81: data = 'hbf;
      12'h82: data = 'hbf;
      12'h83: data = 'hbf;
      12'h84: data = 'hbf;
      12'h85: data = 'hbf;
      12'h86: data = 'hbf;
      12'h87: data = 'hbf;
      12'h88: data = 'hbf;
      12'h89: data = 'hbf;
      12'h8a: data = 'hbf;
      12'h8b: data = 'hbf;
      12'h8c: data = 'hbf;
      12'h8d: data = 'hbf;
      12'h8e: data = 'hbf;
      12'h8f: data = 'hbf;
      12'h90: data = 'hbf;
      12'h91: data = 'hbf;
      12'h92: data = 'hbf;
      12'h93: data = 'hbf;
      12'h94: data = 'hbf;
      12'h95: data = 'hbf;
      12'h96: data = 'hbf;
      12'h97: data = 'hbf;
      12'h98: data = 'hbf;
      12'h99: data = 'hbf;
      12'h9a: data = 'hbf;
      12'h9b: data = 'hbf;
      12'h9c: data = 'hbf;
      12'h9d: data = 'hbf;
      12'h9e: data = 'hbf;
      12'h9f: data = 'hbf;
      12'ha0: data = 'hbf;
      12'ha1: data = 'hbf;
      12'ha2: data = 'hbf;
      12'ha3: data = 'hbf;
      12'ha4: data = 'hbf;
      12'ha5: data = 'hbf;
      12'ha6: data = 'hbf;
      12'ha7: data = 'hbf;
      12'ha8: data = 'hbf;
      12'ha9: data = 'hbf;
      12'haa: data = 'hbf;
      12'hab: data = 'hbf;
      12'hac: data = 'hbf;
      12'had: data = 'hbf;
      12'hae: data = 'hbf;
      12'haf: data = 'hbf;
      12'hb0: data = 'hbf;
      12'hb1: data = 'hbf;
      12'hb2: data = 'hbf;
      12'hb3: data = 'hbf;
      12'hb4: data = 'hbf;
      12'hb5: data = 'hbf;
      12'hb6: data = 'hbf;
      12'hb7: data = 'hbf;
      12'hb8: data = 'hbf;
      12'hb9: data = 'hbf;
      12'hba: data = 'hbf;
      12'hbb: data = 'hbf;
      12'hbc: data = 'hbf;
      12'hbd: data = 'hbf;
      12'hbe: data = 'hbf;
      12'hbf: data = 'hbf;
      12'hc0: data = 'hbf;
      12'hc1: data = 'hbf;
      12'hc2: data = 'hbf;
      12'hc3: data = 'hbf;
      12'hc4: data = 'hbf;
      12'hc5: data = 'hbf;
      12'hc6: data = 'hbf;
      12'hc7: data = 'hbf;
      12'hc8: data = 'hbf;
      12'hc9: data = 'hbf;
      12'hca: data = 'hbf;
      12'hcb: data = 'hbf;
      12'hcc: data = 'hbf;
      12'hcd: data = 'hbf;
      12'hce: data = 'hbf;
      12'hcf: data = 'hbf;
      12'hd0: data = 'hbf;
      12'hd1: data = 'hbf;
      12'hd2: data = 'hbf;
      12'hd3: data = 'hbf;
      12'hd4: data = 'hbf;
      12'hd5: data = 'hbf;
      12'hd6: data = 'hbf;
      12'hd7: data = 'hbf;
      12'hd8: data = 'hbf;
      12'hd9: data = 'hbf;
      12'hda: data = 'hbf;
      12'hdb: data = 'hbf;
      12'hdc: data = 'hbf;
      12'hdd: data = 'hbf;
      12'hde: data = 'hbf;
      12'hdf: data = 'hbf;
      12'he0: data = 'hbf;
      12'he1: data = 'hbf;
      12'he2: data = 'hbf;
      12'he3: data = 'hbf;
      12'he4: data = 'hbf;
      12'he5: data = 'hbf;
      12'he6: data = 'hbf;
      12'he7: data = 'hbf;
      12'he8: data = 'hbf;
      12'he9: data = 'hbf;
      12'hea: data = 'hbf;
      12'heb: data = 'hbf;
      12'hec: data = 'hbf;
      12'hed: data = 'hbf;
      12'hee: data = 'hbf;
      12'hef: data = 'hbf;
      12'hf0: data = 'hbf;
      12'hf1: data = 'hbf;
      12'hf2: data = 'hbf;
      12'hf3: data = 'hbf;
      12'hf4: data = 'hbf;
      12'hf5: data = 'hbf;
      12'hf6: data = 'hbf;
      12'hf7: data = 'hbf;
      12'hf8: data = 'hbf;
      12'hf9: data = 'hbf;
      12'hfa: data = 'hbf;
      12'hfb: data = 'hbf;
      12'hfc: data = 'hbf;
      12'hfd: data = 'hbf;
      12'hfe: data = 'hbf;
      12'hff: data = 'hbf;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$opacity$0
module top$pipeline$opacity$1(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 'h0;
      12'h1: data = 'h0;
      12'h2: data = 'h0;
      12'h3: data = 'h0;
      12'h4: data = 'h0;
      12'h5: data = 'h0;
      12'h6: data = 'h0;
      12'h7: data = 'h0;
      12'h8: data = 'h0;
      12'h9: data = 'h0;
      12'ha: data = 'h0;
      12'hb: data = 'h0;
      12'hc: data = 'h0;
      12'hd: data = 'h0;
      12'he: data = 'h0;
      12'hf: data = 'h0;
      12'h10: data = 'h0;
      12'h11: data = 'h0;
      12'h12: data = 'h0;
      12'h13: data = 'h0;
      12'h14: data = 'h0;
      12'h15: data = 'h0;
      12'h16: data = 'h0;
      12'h17: data = 'h0;
      12'h18: data = 'h0;
      12'h19: data = 'h0;
      12'h1a: data = 'h0;
      12'h1b: data = 'h0;
      12'h1c: data = 'h0;
      12'h1d: data = 'h0;
      12'h1e: data = 'h0;
      12'h1f: data = 'h0;
      12'h20: data = 'h0;
      12'h21: data = 'h0;
      12'h22: data = 'h0;
      12'h23: data = 'h0;
      12'h24: data = 'h0;
      12'h25: data = 'h0;
      12'h26: data = 'h0;
      12'h27: data = 'h0;
      12'h28: data = 'h0;
      12'h29: data = 'h0;
      12'h2a: data = 'h0;
      12'h2b: data = 'h0;
      12'h2c: data = 'h0;
      12'h2d: data = 'h0;
      12'h2e: data = 'h0;
      12'h2f: data = 'h0;
      12'h30: data = 'h0;
      12'h31: data = 'h0;
      12'h32: data = 'h0;
      12'h33: data = 'h0;
      12'h34: data = 'h0;
      12'h35: data = 'h0;
      12'h36: data = 'h0;
      12'h37: data = 'h0;
      12'h38: data = 'h0;
      12'h39: data = 'h0;
      12'h3a: data = 'h0;
      12'h3b: data = 'h0;
      12'h3c: data = 'h0;
      12'h3d: data = 'h0;
      12'h3e: data = 'h0;
      12'h3f: data = 'h0;
      12'h40: data = 'h0;
      12'h41: data = 'h0;
      12'h42: data = 'h0;
      12'h43: data = 'h0;
      12'h44: data = 'h0;
      12'h45: data = 'h0;
      12'h46: data = 'h0;
      12'h47: data = 'h0;
      12'h48: data = 'h0;
      12'h49: data = 'h0;
      12'h4a: data = 'h0;
      12'h4b: data = 'h0;
      12'h4c: data = 'h0;
      12'h4d: data = 'h0;
      12'h4e: data = 'h0;
      12'h4f: data = 'h0;
      12'h50: data = 'h0;
      12'h51: data = 'ha;
      12'h52: data = 'h13;
      12'h53: data = 'h1d;
      12'h54: data = 'h26;
      12'h55: data = 'h30;
      12'h56: data = 'h39;
      12'h57: data = 'h43;
      12'h58: data = 'h4d;
      12'h59: data = 'h56;
      12'h5a: data = 'h60;
      12'h5b: data = 'h69;
      12'h5c: data = 'h73;
      12'h5d: data = 'h7c;
      12'h5e: data = 'h86;
      12'h5f: data = 'h8f;
      12'h60: data = 'h99;
      12'h61: data = 'ha3;
      12'h62: data = 'hac;
      12'h63: data = 'hb6;
      12'h64: data = 'hbf;
      12'h65: data = 'hbf;
      12'h66: data = 'hbf;
      12'h67: data = 'hbf;
      12'h68: data = 'hbf;
      12'h69: data = 'hbf;
      12'h6a: data = 'hbf;
      12'h6b: data = 'hbf;
      12'h6c: data = 'hbf;
      12'h6d: data = 'hbf;
      12'h6e: data = 'hbf;
      12'h6f: data = 'hbf;
      12'h70: data = 'hbf;
      12'h71: data = 'hbf;
      12'h72: data = 'hbf;
      12'h73: data = 'hbf;
      12'h74: data = 'hbf;
      12'h75: data = 'hbf;
      12'h76: data = 'hbf;
      12'h77: data = 'hbf;
      12'h78: data = 'hbf;
      12'h79: data = 'hbf;
      12'h7a: data = 'hbf;
      12'h7b: data = 'hbf;
      12'h7c: data = 'hbf;
      12'h7d: data = 'hbf;
      12'h7e: data = 'hbf;
      12'h7f: data = 'hbf;
      12'h80: data = 'hbf;
      12'h81: data = 'hbf;
      12'h82: data = 'hbf;
      12'h83: data = 'hbf;
      12'h84: data = 'hbf;
      12'h85: data = 'hbf;
      12'h86: data = 'hbf;
      12'h87: data = 'hbf;
      12'h88: data = 'hbf;
      12'h89: data = 'hbf;
      12'h8a: data = 'hbf;
      12'h8b: data = 'hbf;
      12'h8c: data = 'hbf;
      12'h8d: data = 'hbf;
      12'h8e: data = 'hbf;
      12'h8f: data = 'hbf;
      12'h90: data = 'hbf;
      12'h91: data = 'hbf;
      12'h92: data = 'hbf;
      12'h93: data = 'hbf;
      12'h94: data = 'hbf;
      12'h95: data = 'hbf;
      12'h96: data = 'hbf;
      12'h97: data = 'hbf;
      12'h98: data = 'hbf;
      12'h99: data = 'hbf;
      12'h9a: data = 'hbf;
      12'h9b: data = 'hbf;
      12'h9c: data = 'hbf;
      12'h9d: data = 'hbf;
      12'h9e: data = 'hbf;
      12'h9f: data = 'hbf;
      12'ha0: data = 'hbf;
      12'ha1: data = 'hbf;
      12'ha2: data = 'hbf;
      12'ha3: data = 'hbf;
      12'ha4: data = 'hbf;
      12'ha5: data = 'hbf;
      12'ha6: data = 'hbf;
      12'ha7: data = 'hbf;
      12'ha8: data = 'hbf;
      12'ha9: data = 'hbf;
      12'haa: data = 'hbf;
      12'hab: data = 'hbf;
      12'hac: data = 'hbf;
      12'had: data = 'hbf;
      12'hae: data = 'hbf;
      12'haf: data = 'hbf;
      12'hb0: data = 'hbf;
      12'hb1: data = 'hbf;
      12'hb2: data = 'hbf;
      12'hb3: data = 'hbf;
      12'hb4: data = 'hbf;
      12'hb5: data = 'hbf;
      12'hb6: data = 'hbf;
      12'hb7: data = 'hbf;
      12'hb8: data = 'hbf;
      12'hb9: data = 'hbf;
      12'hba: data = 'hbf;
      12'hbb: data = 'hbf;
      12'hbc: data = 'hbf;
      12'hbd: data = 'hbf;
      12'hbe: data = 'hbf;
      12'hbf: data = 'hbf;
      12'hc0: data = 'hbf;
      12'hc1: data = 'hbf;
      12'hc2: data = 'hbf;
      12'hc3: data = 'hbf;
      12'hc4: data = 'hbf;
      12'hc5: data = 'hbf;
      12'hc6: data = 'hbf;
      12'hc7: data = 'hbf;
      12'hc8: data = 'hbf;
      12'hc9: data = 'hbf;
      12'hca: data = 'hbf;
      12'hcb: data = 'hbf;
      12'hcc: data = 'hbf;
      12'hcd: data = 'hbf;
      12'hce: data = 'hbf;
      12'hcf: data = 'hbf;
      12'hd0: data = 'hbf;
      12'hd1: data = 'hbf;
      12'hd2: data = 'hbf;
      12'hd3: data = 'hbf;
      12'hd4: data = 'hbf;
      12'hd5: data = 'hbf;
      12'hd6: data = 'hbf;
      12'hd7: data = 'hbf;
      12'hd8: data = 'hbf;
      12'hd9: data = 'hbf;
      12'hda: data = 'hbf;
      12'hdb: data = 'hbf;
      12'hdc: data = 'hbf;
      12'hdd: data = 'hbf;
      12'hde: data = 'hbf;
      12'hdf: data = 'hbf;
      12'he0: data = 'hbf;
      12'he1: data = 'hbf;
      12'he2: data = 'hbf;
      12'he3: data = 'hbf;
      12'he4: data = 'hbf;
      12'he5: data = 'hbf;
      12'he6: data = 'hbf;
      12'he7: data = 'hbf;
      12'he8: data = 'hbf;
      12'he9: data = 'hbf;
      12'hea: data = 'hbf;
      12'heb: data = 'hbf;
      12'hec: data = 'hbf;
      12'hed: data = 'hbf;
      12'hee: data = 'hbf;
      12'hef: data = 'hbf;
      12'hf0: data = 'hbf;
      12'hf1: data = 'hbf;
      12'hf2: data = 'hbf;
      12'hf3: data = 'hbf;
      12'hf4: data = 'hbf;
      12'hf5: data = 'hbf;
      12'hf6: data = 'hbf;
      12'hf7: data = 'hbf;
      12'hf8: data = 'hbf;
      12'hf9: data = 'hbf;
      12'hfa: data = 'hbf;
      12'hfb: data = 'hbf;
      12'hfc: data = 'hbf;
      12'hfd: data = 'hbf;
      12'hfe: data = 'hbf;
      12'hff: data = 'hbf;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$opacity$1
module top$pipeline$rpc_flags_q(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc_flags_q
module top$pipeline$shade_flags_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade_flags_q$0
module top$pipeline$shade_flags_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade_flags_q$1
module top$pipeline$shade_flags_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade_flags_q$2
module top$pipeline$shade_flags_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade_flags_q$3
module top$pipeline$shade_flags_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade_flags_q$4
module top$pipeline$shade_flags_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade_flags_q$5
