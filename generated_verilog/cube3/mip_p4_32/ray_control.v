module top$pipeline$control(clock,start,valid,first,unit_valid,unit_first,unit_last,unit_cast,wx$0,wx$1,wx$2,wx$3,wy$0,wy$1,wy$2,wy$3,in_volume,in_inner,dx_neg,dx_mag,dy_neg,dy_mag);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  valid;
    output reg  first;
    output reg  unit_valid;
    output reg  unit_first;
    output reg  unit_last;
    output reg  unit_cast;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wx$2;
    output reg  [15:0] wx$3;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [15:0] wy$2;
    output reg  [15:0] wy$3;
    output reg  [7:0] in_volume;
    output reg  [7:0] in_inner;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    
    // Constant declarations
    localparam  last_segment = 16'h7;
    localparam  last_ray = 16'h3b;
    localparam  late_last = 16'h8;
    localparam  cast_ray_lo = 16'h0;
    localparam  cast_ray_span = 16'h3b;
    localparam  cast_line_lo = 16'h0;
    localparam  cast_line_span = 16'h2f;
    localparam  per_ray = 1'b0;
    localparam  lane_bit$0 = 8'h1;
    localparam  lane_bit$1 = 8'h2;
    localparam  lane_bit$2 = 8'h4;
    localparam  lane_bit$3 = 8'h8;
    localparam  lane_bit$4 = 8'h10;
    localparam  lane_bit$5 = 8'h20;
    localparam  lane_bit$6 = 8'h40;
    localparam  lane_bit$7 = 8'h80;
    localparam  valid_flag = 64'h1000000000000;
    
    // Stub signals
    reg  [15:0] segment$d;
    wire  [15:0] segment$q;
    reg  segment$clock;
    reg  [15:0] ray$d;
    wire  [15:0] ray$q;
    reg  ray$clock;
    reg  [15:0] scanline$d;
    wire  [15:0] scanline$q;
    reg  scanline$clock;
    reg  late$clock;
    reg  [63:0] late$data_in;
    reg  late$write_enable;
    wire  [63:0] late$data_out;
    reg  [15:0] late$last;
    reg  [15:0] templates$ray;
    reg  [15:0] templates$scanline;
    reg  [15:0] templates$segment;
    wire  [15:0] templates$wx$0;
    wire  [15:0] templates$wx$1;
    wire  [15:0] templates$wx$2;
    wire  [15:0] templates$wx$3;
    wire  [15:0] templates$wy$0;
    wire  [15:0] templates$wy$1;
    wire  [15:0] templates$wy$2;
    wire  [15:0] templates$wy$3;
    reg  increments$clock;
    reg  [15:0] increments$ray;
    reg  [15:0] increments$scanline;
    wire  increments$dx_neg;
    wire  [15:0] increments$dx_mag;
    wire  increments$dy_neg;
    wire  [15:0] increments$dy_mag;
    reg  [7:0] bounds$0$address;
    wire  [63:0] bounds$0$data;
    reg  [7:0] bounds$1$address;
    wire  [63:0] bounds$1$data;
    reg  [7:0] bounds$2$address;
    wire  [63:0] bounds$2$data;
    reg  [7:0] bounds$3$address;
    wire  [63:0] bounds$3$data;
    reg  [7:0] inner$0$address;
    wire  [63:0] inner$0$data;
    reg  [7:0] inner$1$address;
    wire  [63:0] inner$1$data;
    reg  [7:0] inner$2$address;
    wire  [63:0] inner$2$data;
    reg  [7:0] inner$3$address;
    wire  [63:0] inner$3$data;
    
    // Local signals
    reg  [15:0] unit_segment;
    reg  [15:0] unit_ray;
    reg  [15:0] unit_scanline;
    reg  [7:0] lane_in$0;
    reg  [7:0] lane_in$1;
    reg  [7:0] lane_in$2;
    reg  [7:0] lane_in$3;
    reg  [7:0] lane_in$4;
    reg  [7:0] lane_in$5;
    reg  [7:0] lane_in$6;
    reg  [7:0] lane_in$7;
    reg  [7:0] lane_inner$0;
    reg  [7:0] lane_inner$1;
    reg  [7:0] lane_inner$2;
    reg  [7:0] lane_inner$3;
    reg  [7:0] lane_inner$4;
    reg  [7:0] lane_inner$5;
    reg  [7:0] lane_inner$6;
    reg  [7:0] lane_inner$7;
    
    // Sub module instances
    top$pipeline$control$segment segment(
        .d(segment$d),
        .q(segment$q),
        .clock(segment$clock)
    );
    top$pipeline$control$ray ray(
        .d(ray$d),
        .q(ray$q),
        .clock(ray$clock)
    );
    top$pipeline$control$scanline scanline(
        .d(scanline$d),
        .q(scanline$q),
        .clock(scanline$clock)
    );
    top$pipeline$control$late late(
        .clock(late$clock),
        .data_in(late$data_in),
        .write_enable(late$write_enable),
        .data_out(late$data_out),
        .last(late$last)
    );
    top$pipeline$control$templates templates(
        .ray(templates$ray),
        .scanline(templates$scanline),
        .segment(templates$segment),
        .wx$0(templates$wx$0),
        .wx$1(templates$wx$1),
        .wx$2(templates$wx$2),
        .wx$3(templates$wx$3),
        .wy$0(templates$wy$0),
        .wy$1(templates$wy$1),
        .wy$2(templates$wy$2),
        .wy$3(templates$wy$3)
    );
    top$pipeline$control$increments increments(
        .clock(increments$clock),
        .ray(increments$ray),
        .scanline(increments$scanline),
        .dx_neg(increments$dx_neg),
        .dx_mag(increments$dx_mag),
        .dy_neg(increments$dy_neg),
        .dy_mag(increments$dy_mag)
    );
    top$pipeline$control$bounds$0 bounds$0(
        .address(bounds$0$address),
        .data(bounds$0$data)
    );
    top$pipeline$control$bounds$1 bounds$1(
        .address(bounds$1$address),
        .data(bounds$1$data)
    );
    top$pipeline$control$bounds$2 bounds$2(
        .address(bounds$2$address),
        .data(bounds$2$data)
    );
    top$pipeline$control$bounds$3 bounds$3(
        .address(bounds$3$address),
        .data(bounds$3$data)
    );
    top$pipeline$control$inner$0 inner$0(
        .address(inner$0$address),
        .data(inner$0$data)
    );
    top$pipeline$control$inner$1 inner$1(
        .address(inner$1$address),
        .data(inner$1$data)
    );
    top$pipeline$control$inner$2 inner$2(
        .address(inner$2$address),
        .data(inner$2$data)
    );
    top$pipeline$control$inner$3 inner$3(
        .address(inner$3$address),
        .data(inner$3$data)
    );
    
    // Update code
    always @(*) begin
        segment$clock = clock;
        ray$clock = clock;
        scanline$clock = clock;
        segment$d = segment$q;
        ray$d = ray$q;
        scanline$d = scanline$q;
        late$clock = clock;
        late$last = late_last;
        late$write_enable = 1'b1;
        increments$clock = clock;
        if (valid) begin
            segment$d = segment$q + 'h1;
            if (segment$q == last_segment) begin
                segment$d = 'h0;
                ray$d = ray$q + 'h1;
                if (ray$q == last_ray) begin
                    ray$d = 'h0;
                    scanline$d = scanline$q + 'h1;
                end
            end
        end
        if (start) begin
            segment$d = 'h0;
            ray$d = 'h0;
            scanline$d = 'h0;
        end
        first = valid & ~|segment$q;
        late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20);
        if (valid) begin
            late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20) | valid_flag;
        end
        unit_segment = late$data_out[('h0)+:(16)];
        unit_ray = late$data_out[('h10)+:(16)];
        unit_scanline = late$data_out[('h20)+:(16)];
        unit_valid = late$data_out['h30];
        unit_first = late$data_out['h30] & ~|unit_segment;
        unit_last = late$data_out['h30] & (unit_segment == last_segment);
        unit_cast = ~per_ray | (((unit_ray - cast_ray_lo) <= cast_ray_span) & ((unit_scanline - cast_line_lo) <= cast_line_span));
        increments$ray = unit_ray;
        increments$scanline = unit_scanline;
        dx_neg = increments$dx_neg;
        dx_mag = increments$dx_mag;
        dy_neg = increments$dy_neg;
        dy_mag = increments$dy_mag;
        templates$ray = unit_ray;
        templates$scanline = unit_scanline;
        templates$segment = unit_segment;
        lane_in$0 = 'h0;
        lane_inner$0 = 'h0;
        lane_in$1 = 'h0;
        lane_inner$1 = 'h0;
        lane_in$2 = 'h0;
        lane_inner$2 = 'h0;
        lane_in$3 = 'h0;
        lane_inner$3 = 'h0;
        lane_in$4 = 'h0;
        lane_inner$4 = 'h0;
        lane_in$5 = 'h0;
        lane_inner$5 = 'h0;
        lane_in$6 = 'h0;
        lane_inner$6 = 'h0;
        lane_in$7 = 'h0;
        lane_inner$7 = 'h0;
        bounds$0$address = unit_segment[('h0)+:(8)];
        wx$0 = templates$wx$0;
        wy$0 = templates$wy$0;
        if ((unit_ray >= bounds$0$data[('h0)+:(16)]) & (unit_ray <= bounds$0$data[('h10)+:(16)]) & (unit_scanline >= bounds$0$data[('h20)+:(16)]) & (unit_scanline <= bounds$0$data[('h30)+:(16)])) begin
            lane_in$0 = lane_bit$0;
        end
        inner$0$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$0$data[('h0)+:(16)]) & (unit_ray <= inner$0$data[('h10)+:(16)]) & (unit_scanline >= inner$0$data[('h20)+:(16)]) & (unit_scanline <= inner$0$data[('h30)+:(16)])) begin
            lane_inner$0 = lane_bit$0;
        end
        bounds$1$address = unit_segment[('h0)+:(8)];
        wx$1 = templates$wx$1;
        wy$1 = templates$wy$1;
        if ((unit_ray >= bounds$1$data[('h0)+:(16)]) & (unit_ray <= bounds$1$data[('h10)+:(16)]) & (unit_scanline >= bounds$1$data[('h20)+:(16)]) & (unit_scanline <= bounds$1$data[('h30)+:(16)])) begin
            lane_in$1 = lane_bit$1;
        end
        inner$1$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$1$data[('h0)+:(16)]) & (unit_ray <= inner$1$data[('h10)+:(16)]) & (unit_scanline >= inner$1$data[('h20)+:(16)]) & (unit_scanline <= inner$1$data[('h30)+:(16)])) begin
            lane_inner$1 = lane_bit$1;
        end
        bounds$2$address = unit_segment[('h0)+:(8)];
        wx$2 = templates$wx$2;
        wy$2 = templates$wy$2;
        if ((unit_ray >= bounds$2$data[('h0)+:(16)]) & (unit_ray <= bounds$2$data[('h10)+:(16)]) & (unit_scanline >= bounds$2$data[('h20)+:(16)]) & (unit_scanline <= bounds$2$data[('h30)+:(16)])) begin
            lane_in$2 = lane_bit$2;
        end
        inner$2$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$2$data[('h0)+:(16)]) & (unit_ray <= inner$2$data[('h10)+:(16)]) & (unit_scanline >= inner$2$data[('h20)+:(16)]) & (unit_scanline <= inner$2$data[('h30)+:(16)])) begin
            lane_inner$2 = lane_bit$2;
        end
        bounds$3$address = unit_segment[('h0)+:(8)];
        wx$3 = templates$wx$3;
        wy$3 = templates$wy$3;
        if ((unit_ray >= bounds$3$data[('h0)+:(16)]) & (unit_ray <= bounds$3$data[('h10)+:(16)]) & (unit_scanline >= bounds$3$data[('h20)+:(16)]) & (unit_scanline <= bounds$3$data[('h30)+:(16)])) begin
            lane_in$3 = lane_bit$3;
        end
        inner$3$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$3$data[('h0)+:(16)]) & (unit_ray <= inner$3$data[('h10)+:(16)]) & (unit_scanline >= inner$3$data[('h20)+:(16)]) & (unit_scanline <= inner$3$data[('h30)+:(16)])) begin
            lane_inner$3 = lane_bit$3;
        end
        in_volume = lane_in$0 | lane_in$1 | lane_in$2 | lane_in$3 | lane_in$4 | lane_in$5 | lane_in$6 | lane_in$7;
        in_inner = lane_inner$0 | lane_inner$1 | lane_inner$2 | lane_inner$3 | lane_inner$4 | lane_inner$5 | lane_inner$6 | lane_inner$7;
    end
    
endmodule // top$pipeline$control
module top$pipeline$control$bounds$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h20000100380019;
      8'h1: data = 64'h21000300340016;
      8'h2: data = 64'h23000500310013;
      8'h3: data = 64'h250007002e0010;
      8'h4: data = 64'h270009002b000d;
      8'h5: data = 64'h29000b0028000a;
      8'h6: data = 64'h2b000d00250007;
      8'h7: data = 64'h2d000f00220004;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$0
module top$pipeline$control$bounds$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h20000200370019;
      8'h1: data = 64'h22000400340016;
      8'h2: data = 64'h24000600310013;
      8'h3: data = 64'h260008002d000f;
      8'h4: data = 64'h270009002a000c;
      8'h5: data = 64'h29000b00270009;
      8'h6: data = 64'h2b000d00240006;
      8'h7: data = 64'h2d000f00210003;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$1
module top$pipeline$control$bounds$2(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h20000200360018;
      8'h1: data = 64'h22000400330015;
      8'h2: data = 64'h24000600300012;
      8'h3: data = 64'h260008002d000f;
      8'h4: data = 64'h28000a002a000c;
      8'h5: data = 64'h2a000c00260008;
      8'h6: data = 64'h2c000e00230005;
      8'h7: data = 64'h2d000f00200002;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$2
module top$pipeline$control$bounds$3(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h21000300350017;
      8'h1: data = 64'h23000500320014;
      8'h2: data = 64'h250007002f0011;
      8'h3: data = 64'h260008002c000e;
      8'h4: data = 64'h28000a0029000b;
      8'h5: data = 64'h2a000c00260008;
      8'h6: data = 64'h2c000e00230005;
      8'h7: data = 64'h2e001000000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$3
module top$pipeline$control$increments(clock,ray,scanline,dx_neg,dx_mag,dy_neg,dy_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] ray;
    input wire  [15:0] scanline;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    
    // Constant declarations
    localparam  centre_last = 16'h0;
    localparam  mask = 16'h0;
    
    // Stub signals
    reg  centre_line$clock;
    reg  [31:0] centre_line$data_in;
    reg  centre_line$write_enable;
    wire  [31:0] centre_line$data_out;
    reg  [15:0] centre_line$last;
    reg  [15:0] dx_rom$address;
    wire  [16:0] dx_rom$data;
    reg  [15:0] dy_rom$address;
    wire  [16:0] dy_rom$data;
    
    // Local signals
    reg  [15:0] dx_address;
    reg  [15:0] dy_address;
    
    // Sub module instances
    top$pipeline$control$increments$centre_line centre_line(
        .clock(centre_line$clock),
        .data_in(centre_line$data_in),
        .write_enable(centre_line$write_enable),
        .data_out(centre_line$data_out),
        .last(centre_line$last)
    );
    top$pipeline$control$increments$dx_rom dx_rom(
        .address(dx_rom$address),
        .data(dx_rom$data)
    );
    top$pipeline$control$increments$dy_rom dy_rom(
        .address(dy_rom$address),
        .data(dy_rom$data)
    );
    
    // Update code
    always @(*) begin
        centre_line$clock = clock;
        centre_line$last = centre_last;
        centre_line$write_enable = 1'b1;
        centre_line$data_in = 32'(ray) | (32'(scanline) << 'h10);
        dx_address = centre_line$data_out[('h0)+:(16)] & mask;
        dy_address = (centre_line$data_out[('h10)+:(16)] - 'h1) & mask;
        dx_rom$address = dx_address;
        dy_rom$address = dy_address;
        dx_neg = dx_rom$data['h10];
        dx_mag = dx_rom$data[('h0)+:(16)];
        dy_neg = dy_rom$data['h10];
        dy_mag = dy_rom$data[('h0)+:(16)];
    end
    
endmodule // top$pipeline$control$increments
module top$pipeline$control$increments$centre_line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h1;
    localparam  single = 1'b1;
    localparam  mask = 'hffffffff;
    
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
    top$pipeline$control$increments$centre_line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$increments$centre_line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$increments$centre_line$one one(
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
    
endmodule // top$pipeline$control$increments$centre_line
module top$pipeline$control$increments$centre_line$one(d,q,clock);
    
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
          
endmodule // top$pipeline$control$increments$centre_line$one
module top$pipeline$control$increments$centre_line$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$control$increments$centre_line$ptr
module top$pipeline$control$increments$centre_line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[0:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$increments$centre_line$ram
module top$pipeline$control$increments$dx_rom(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        16'h0: data = 17'b0;
      default: data = 17'b0;
    endcase
            
endmodule // top$pipeline$control$increments$dx_rom
module top$pipeline$control$increments$dy_rom(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        16'h0: data = 17'b0;
      default: data = 17'b0;
    endcase
            
endmodule // top$pipeline$control$increments$dy_rom
module top$pipeline$control$inner$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$0
module top$pipeline$control$inner$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$1
module top$pipeline$control$inner$2(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$2
module top$pipeline$control$inner$3(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$3
module top$pipeline$control$late(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h8;
    localparam  single = 1'b0;
    localparam  mask = 64'hffffffffffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$control$late$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$late$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$late$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
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
    
endmodule // top$pipeline$control$late
module top$pipeline$control$late$one(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$one
module top$pipeline$control$late$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$ptr
module top$pipeline$control$late$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [63:0] mem[8:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[3:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[3:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$late$ram
module top$pipeline$control$ray(d,q,clock);
    
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
          
endmodule // top$pipeline$control$ray
module top$pipeline$control$scanline(d,q,clock);
    
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
          
endmodule // top$pipeline$control$scanline
module top$pipeline$control$segment(d,q,clock);
    
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
          
endmodule // top$pipeline$control$segment
module top$pipeline$control$templates(ray,scanline,segment,wx$0,wx$1,wx$2,wx$3,wy$0,wy$1,wy$2,wy$3);
    
    // Module arguments
    input wire  [15:0] ray;
    input wire  [15:0] scanline;
    input wire  [15:0] segment;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wx$2;
    output reg  [15:0] wx$3;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [15:0] wy$2;
    output reg  [15:0] wy$3;
    
    // Constant declarations
    localparam  stride = 16'h0;
    
    // Stub signals
    reg  [31:0] wx_rom$0$address;
    wire  [15:0] wx_rom$0$data;
    reg  [31:0] wx_rom$1$address;
    wire  [15:0] wx_rom$1$data;
    reg  [31:0] wx_rom$2$address;
    wire  [15:0] wx_rom$2$data;
    reg  [31:0] wx_rom$3$address;
    wire  [15:0] wx_rom$3$data;
    reg  [31:0] wy_rom$0$address;
    wire  [15:0] wy_rom$0$data;
    reg  [31:0] wy_rom$1$address;
    wire  [15:0] wy_rom$1$data;
    reg  [31:0] wy_rom$2$address;
    wire  [15:0] wy_rom$2$data;
    reg  [31:0] wy_rom$3$address;
    wire  [15:0] wy_rom$3$data;
    
    // Local signals
    reg  [31:0] wx_entry;
    reg  [31:0] wy_entry;
    
    // Sub module instances
    top$pipeline$control$templates$wx_rom$0 wx_rom$0(
        .address(wx_rom$0$address),
        .data(wx_rom$0$data)
    );
    top$pipeline$control$templates$wx_rom$1 wx_rom$1(
        .address(wx_rom$1$address),
        .data(wx_rom$1$data)
    );
    top$pipeline$control$templates$wx_rom$2 wx_rom$2(
        .address(wx_rom$2$address),
        .data(wx_rom$2$data)
    );
    top$pipeline$control$templates$wx_rom$3 wx_rom$3(
        .address(wx_rom$3$address),
        .data(wx_rom$3$data)
    );
    top$pipeline$control$templates$wy_rom$0 wy_rom$0(
        .address(wy_rom$0$address),
        .data(wy_rom$0$data)
    );
    top$pipeline$control$templates$wy_rom$1 wy_rom$1(
        .address(wy_rom$1$address),
        .data(wy_rom$1$data)
    );
    top$pipeline$control$templates$wy_rom$2 wy_rom$2(
        .address(wy_rom$2$address),
        .data(wy_rom$2$data)
    );
    top$pipeline$control$templates$wy_rom$3 wy_rom$3(
        .address(wy_rom$3$address),
        .data(wy_rom$3$data)
    );
    
    // Update code
    always @(*) begin
        wx_entry = ray * stride + 32'(segment);
        wy_entry = scanline * stride + 32'(segment);
        wx_rom$0$address = wx_entry;
        wy_rom$0$address = wy_entry;
        wx$0 = wx_rom$0$data;
        wy$0 = wy_rom$0$data;
        wx_rom$1$address = wx_entry;
        wy_rom$1$address = wy_entry;
        wx$1 = wx_rom$1$data;
        wy$1 = wy_rom$1$data;
        wx_rom$2$address = wx_entry;
        wy_rom$2$address = wy_entry;
        wx$2 = wx_rom$2$data;
        wy$2 = wy_rom$2$data;
        wx_rom$3$address = wx_entry;
        wy_rom$3$address = wy_entry;
        wx$3 = wx_rom$3$data;
        wy$3 = wy_rom$3$data;
    end
    
endmodule // top$pipeline$control$templates
module top$pipeline$control$templates$wx_rom$0(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h0;
      'h1: data = 16'h18;
      'h2: data = 16'h30;
      'h3: data = 16'h38;
      'h4: data = 16'h50;
      'h5: data = 16'h68;
      'h6: data = 16'h80;
      'h7: data = 16'h98;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wx_rom$0
module top$pipeline$control$templates$wx_rom$1(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'hb6;
      'h1: data = 16'hce;
      'h2: data = 16'he6;
      'h3: data = 16'he;
      'h4: data = 16'h26;
      'h5: data = 16'h2e;
      'h6: data = 16'h46;
      'h7: data = 16'h5e;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wx_rom$1
module top$pipeline$control$templates$wx_rom$2(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h7c;
      'h1: data = 16'h94;
      'h2: data = 16'hac;
      'h3: data = 16'hc4;
      'h4: data = 16'hdc;
      'h5: data = 16'h4;
      'h6: data = 16'h1c;
      'h7: data = 16'h34;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wx_rom$2
module top$pipeline$control$templates$wx_rom$3(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h42;
      'h1: data = 16'h5a;
      'h2: data = 16'h72;
      'h3: data = 16'h8a;
      'h4: data = 16'ha2;
      'h5: data = 16'hba;
      'h6: data = 16'hd2;
      'h7: data = 16'hea;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wx_rom$3
module top$pipeline$control$templates$wy_rom$0(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h10;
      'h1: data = 16'h34;
      'h2: data = 16'h58;
      'h3: data = 16'h7c;
      'h4: data = 16'h90;
      'h5: data = 16'hb4;
      'h6: data = 16'hd8;
      'h7: data = 16'hfc;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wy_rom$0
module top$pipeline$control$templates$wy_rom$1(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h89;
      'h1: data = 16'had;
      'h2: data = 16'hd1;
      'h3: data = 16'hf5;
      'h4: data = 16'h29;
      'h5: data = 16'h4d;
      'h6: data = 16'h71;
      'h7: data = 16'h85;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wy_rom$1
module top$pipeline$control$templates$wy_rom$2(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h22;
      'h1: data = 16'h46;
      'h2: data = 16'h6a;
      'h3: data = 16'h7e;
      'h4: data = 16'ha2;
      'h5: data = 16'hc6;
      'h6: data = 16'hea;
      'h7: data = 16'h1e;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wy_rom$2
module top$pipeline$control$templates$wy_rom$3(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h9b;
      'h1: data = 16'hbf;
      'h2: data = 16'he3;
      'h3: data = 16'h17;
      'h4: data = 16'h3b;
      'h5: data = 16'h5f;
      'h6: data = 16'h83;
      'h7: data = 16'h97;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wy_rom$3
