module top$pipeline$control(clock,start,valid,first,unit_valid,unit_first,unit_last,unit_cast,wx$0,wx$1,wy$0,wy$1,in_volume,in_inner,dx_neg,dx_mag,dy_neg,dy_mag);
    
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
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [7:0] in_volume;
    output reg  [7:0] in_inner;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    
    // Constant declarations
    localparam  last_segment = 16'h7f;
    localparam  last_ray = 16'hce;
    localparam  late_last = 16'h80;
    localparam  cast_ray_lo = 16'h0;
    localparam  cast_ray_span = 16'hce;
    localparam  cast_line_lo = 16'h0;
    localparam  cast_line_span = 16'h19d;
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
    wire  [15:0] templates$wy$0;
    wire  [15:0] templates$wy$1;
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
    reg  [7:0] inner$0$address;
    wire  [63:0] inner$0$data;
    reg  [7:0] inner$1$address;
    wire  [63:0] inner$1$data;
    
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
        .wy$0(templates$wy$0),
        .wy$1(templates$wy$1)
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
    top$pipeline$control$inner$0 inner$0(
        .address(inner$0$address),
        .data(inner$0$data)
    );
    top$pipeline$control$inner$1 inner$1(
        .address(inner$1$address),
        .data(inner$1$data)
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
        8'h0: data = 64'h19c009d006f0002;
      8'h1: data = 64'h19a009c006f0003;
      8'h2: data = 64'h199009b00700004;
      8'h3: data = 64'h198009a00710005;
      8'h4: data = 64'h197009900710005;
      8'h5: data = 64'h195009700720006;
      8'h6: data = 64'h194009600730007;
      8'h7: data = 64'h193009500740008;
      8'h8: data = 64'h192009400740008;
      8'h9: data = 64'h190009200750009;
      8'ha: data = 64'h18f00910076000a;
      8'hb: data = 64'h18e00900076000a;
      8'hc: data = 64'h18d008f0077000b;
      8'hd: data = 64'h18c008e0078000c;
      8'he: data = 64'h18a008c0079000d;
      8'hf: data = 64'h189008b0079000d;
      8'h10: data = 64'h188008a007a000e;
      8'h11: data = 64'h1870089007b000f;
      8'h12: data = 64'h1850087007c0010;
      8'h13: data = 64'h1840086007c0010;
      8'h14: data = 64'h1830085007d0011;
      8'h15: data = 64'h1820084007e0012;
      8'h16: data = 64'h1810083007e0012;
      8'h17: data = 64'h17f0081007f0013;
      8'h18: data = 64'h17e008000800014;
      8'h19: data = 64'h17d007f00810015;
      8'h1a: data = 64'h17c007e00810015;
      8'h1b: data = 64'h17a007c00820016;
      8'h1c: data = 64'h179007b00830017;
      8'h1d: data = 64'h178007a00840018;
      8'h1e: data = 64'h177007900840018;
      8'h1f: data = 64'h175007700850019;
      8'h20: data = 64'h17400760086001a;
      8'h21: data = 64'h17300750086001a;
      8'h22: data = 64'h17200740087001b;
      8'h23: data = 64'h17100730088001c;
      8'h24: data = 64'h16f00710089001d;
      8'h25: data = 64'h16e00700089001d;
      8'h26: data = 64'h16d006f008a001e;
      8'h27: data = 64'h16c006e008b001f;
      8'h28: data = 64'h16a006c008c0020;
      8'h29: data = 64'h169006b008c0020;
      8'h2a: data = 64'h168006a008d0021;
      8'h2b: data = 64'h1670069008e0022;
      8'h2c: data = 64'h1660068008e0022;
      8'h2d: data = 64'h1640066008f0023;
      8'h2e: data = 64'h163006500900024;
      8'h2f: data = 64'h162006400910025;
      8'h30: data = 64'h161006300910025;
      8'h31: data = 64'h15f006100920026;
      8'h32: data = 64'h15e006000930027;
      8'h33: data = 64'h15d005f00940028;
      8'h34: data = 64'h15c005e00940028;
      8'h35: data = 64'h15a005c00950029;
      8'h36: data = 64'h159005b0096002a;
      8'h37: data = 64'h158005a0096002a;
      8'h38: data = 64'h15700590097002b;
      8'h39: data = 64'h15600580098002c;
      8'h3a: data = 64'h15400560099002d;
      8'h3b: data = 64'h15300550099002d;
      8'h3c: data = 64'h1520054009a002e;
      8'h3d: data = 64'h1510053009b002f;
      8'h3e: data = 64'h14f0051009c0030;
      8'h3f: data = 64'h14e0050009c0030;
      8'h40: data = 64'h14d004f009d0031;
      8'h41: data = 64'h14c004e009e0032;
      8'h42: data = 64'h14b004d009e0032;
      8'h43: data = 64'h149004b009f0033;
      8'h44: data = 64'h148004a00a00034;
      8'h45: data = 64'h147004900a10035;
      8'h46: data = 64'h146004800a10035;
      8'h47: data = 64'h144004600a20036;
      8'h48: data = 64'h143004500a30037;
      8'h49: data = 64'h142004400a40038;
      8'h4a: data = 64'h141004300a40038;
      8'h4b: data = 64'h140004200a50039;
      8'h4c: data = 64'h13e004000a6003a;
      8'h4d: data = 64'h13d003f00a6003a;
      8'h4e: data = 64'h13c003e00a7003b;
      8'h4f: data = 64'h13b003d00a8003c;
      8'h50: data = 64'h139003b00a9003d;
      8'h51: data = 64'h138003a00a9003d;
      8'h52: data = 64'h137003900aa003e;
      8'h53: data = 64'h136003800ab003f;
      8'h54: data = 64'h134003600ac0040;
      8'h55: data = 64'h133003500ac0040;
      8'h56: data = 64'h132003400ad0041;
      8'h57: data = 64'h131003300ae0042;
      8'h58: data = 64'h130003200ae0042;
      8'h59: data = 64'h12e003000af0043;
      8'h5a: data = 64'h12d002f00b00044;
      8'h5b: data = 64'h12c002e00b10045;
      8'h5c: data = 64'h12b002d00b10045;
      8'h5d: data = 64'h129002b00b20046;
      8'h5e: data = 64'h128002a00b30047;
      8'h5f: data = 64'h127002900b40048;
      8'h60: data = 64'h126002800b40048;
      8'h61: data = 64'h125002700b50049;
      8'h62: data = 64'h123002500b6004a;
      8'h63: data = 64'h122002400b6004a;
      8'h64: data = 64'h121002300b7004b;
      8'h65: data = 64'h120002200b8004c;
      8'h66: data = 64'h11e002000b9004d;
      8'h67: data = 64'h11d001f00b9004d;
      8'h68: data = 64'h11c001e00ba004e;
      8'h69: data = 64'h11b001d00bb004f;
      8'h6a: data = 64'h119001b00bc0050;
      8'h6b: data = 64'h118001a00bc0050;
      8'h6c: data = 64'h117001900bd0051;
      8'h6d: data = 64'h116001800be0052;
      8'h6e: data = 64'h115001700be0052;
      8'h6f: data = 64'h113001500bf0053;
      8'h70: data = 64'h112001400c00054;
      8'h71: data = 64'h111001300c10055;
      8'h72: data = 64'h110001200c10055;
      8'h73: data = 64'h10e001000c20056;
      8'h74: data = 64'h10d000f00c30057;
      8'h75: data = 64'h10c000e00c40058;
      8'h76: data = 64'h10b000d00c40058;
      8'h77: data = 64'h10a000c00c50059;
      8'h78: data = 64'h108000a00c6005a;
      8'h79: data = 64'h107000900c6005a;
      8'h7a: data = 64'h106000800c7005b;
      8'h7b: data = 64'h105000700c8005c;
      8'h7c: data = 64'h103000500c9005d;
      8'h7d: data = 64'h102000400c9005d;
      8'h7e: data = 64'h101000300ca005e;
      8'h7f: data = 64'h100000200cb005f;
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
        8'h0: data = 64'h19b009d006f0003;
      8'h1: data = 64'h19a009c00700004;
      8'h2: data = 64'h198009a00700004;
      8'h3: data = 64'h197009900710005;
      8'h4: data = 64'h196009800720006;
      8'h5: data = 64'h195009700720006;
      8'h6: data = 64'h194009600730007;
      8'h7: data = 64'h192009400740008;
      8'h8: data = 64'h191009300750009;
      8'h9: data = 64'h190009200750009;
      8'ha: data = 64'h18f00910076000a;
      8'hb: data = 64'h18d008f0077000b;
      8'hc: data = 64'h18c008e0078000c;
      8'hd: data = 64'h18b008d0078000c;
      8'he: data = 64'h18a008c0079000d;
      8'hf: data = 64'h188008a007a000e;
      8'h10: data = 64'h1870089007a000e;
      8'h11: data = 64'h1860088007b000f;
      8'h12: data = 64'h1850087007c0010;
      8'h13: data = 64'h1840086007d0011;
      8'h14: data = 64'h1820084007d0011;
      8'h15: data = 64'h1810083007e0012;
      8'h16: data = 64'h1800082007f0013;
      8'h17: data = 64'h17f008100800014;
      8'h18: data = 64'h17d007f00800014;
      8'h19: data = 64'h17c007e00810015;
      8'h1a: data = 64'h17b007d00820016;
      8'h1b: data = 64'h17a007c00820016;
      8'h1c: data = 64'h179007b00830017;
      8'h1d: data = 64'h177007900840018;
      8'h1e: data = 64'h176007800850019;
      8'h1f: data = 64'h175007700850019;
      8'h20: data = 64'h17400760086001a;
      8'h21: data = 64'h17200740087001b;
      8'h22: data = 64'h17100730088001c;
      8'h23: data = 64'h17000720088001c;
      8'h24: data = 64'h16f00710089001d;
      8'h25: data = 64'h16e0070008a001e;
      8'h26: data = 64'h16c006e008a001e;
      8'h27: data = 64'h16b006d008b001f;
      8'h28: data = 64'h16a006c008c0020;
      8'h29: data = 64'h169006b008d0021;
      8'h2a: data = 64'h1670069008d0021;
      8'h2b: data = 64'h1660068008e0022;
      8'h2c: data = 64'h1650067008f0023;
      8'h2d: data = 64'h164006600900024;
      8'h2e: data = 64'h162006400900024;
      8'h2f: data = 64'h161006300910025;
      8'h30: data = 64'h160006200920026;
      8'h31: data = 64'h15f006100920026;
      8'h32: data = 64'h15e006000930027;
      8'h33: data = 64'h15c005e00940028;
      8'h34: data = 64'h15b005d00950029;
      8'h35: data = 64'h15a005c00950029;
      8'h36: data = 64'h159005b0096002a;
      8'h37: data = 64'h15700590097002b;
      8'h38: data = 64'h15600580098002c;
      8'h39: data = 64'h15500570098002c;
      8'h3a: data = 64'h15400560099002d;
      8'h3b: data = 64'h1530055009a002e;
      8'h3c: data = 64'h1510053009a002e;
      8'h3d: data = 64'h1500052009b002f;
      8'h3e: data = 64'h14f0051009c0030;
      8'h3f: data = 64'h14e0050009d0031;
      8'h40: data = 64'h14c004e009d0031;
      8'h41: data = 64'h14b004d009e0032;
      8'h42: data = 64'h14a004c009f0033;
      8'h43: data = 64'h149004b00a00034;
      8'h44: data = 64'h147004900a00034;
      8'h45: data = 64'h146004800a10035;
      8'h46: data = 64'h145004700a20036;
      8'h47: data = 64'h144004600a20036;
      8'h48: data = 64'h143004500a30037;
      8'h49: data = 64'h141004300a40038;
      8'h4a: data = 64'h140004200a50039;
      8'h4b: data = 64'h13f004100a50039;
      8'h4c: data = 64'h13e004000a6003a;
      8'h4d: data = 64'h13c003e00a7003b;
      8'h4e: data = 64'h13b003d00a8003c;
      8'h4f: data = 64'h13a003c00a8003c;
      8'h50: data = 64'h139003b00a9003d;
      8'h51: data = 64'h138003a00aa003e;
      8'h52: data = 64'h136003800aa003e;
      8'h53: data = 64'h135003700ab003f;
      8'h54: data = 64'h134003600ac0040;
      8'h55: data = 64'h133003500ad0041;
      8'h56: data = 64'h131003300ad0041;
      8'h57: data = 64'h130003200ae0042;
      8'h58: data = 64'h12f003100af0043;
      8'h59: data = 64'h12e003000b00044;
      8'h5a: data = 64'h12c002e00b00044;
      8'h5b: data = 64'h12b002d00b10045;
      8'h5c: data = 64'h12a002c00b20046;
      8'h5d: data = 64'h129002b00b20046;
      8'h5e: data = 64'h128002a00b30047;
      8'h5f: data = 64'h126002800b40048;
      8'h60: data = 64'h125002700b50049;
      8'h61: data = 64'h124002600b50049;
      8'h62: data = 64'h123002500b6004a;
      8'h63: data = 64'h121002300b7004b;
      8'h64: data = 64'h120002200b8004c;
      8'h65: data = 64'h11f002100b8004c;
      8'h66: data = 64'h11e002000b9004d;
      8'h67: data = 64'h11d001f00ba004e;
      8'h68: data = 64'h11b001d00ba004e;
      8'h69: data = 64'h11a001c00bb004f;
      8'h6a: data = 64'h119001b00bc0050;
      8'h6b: data = 64'h118001a00bd0051;
      8'h6c: data = 64'h116001800bd0051;
      8'h6d: data = 64'h115001700be0052;
      8'h6e: data = 64'h114001600bf0053;
      8'h6f: data = 64'h113001500c00054;
      8'h70: data = 64'h112001400c00054;
      8'h71: data = 64'h110001200c10055;
      8'h72: data = 64'h10f001100c20056;
      8'h73: data = 64'h10e001000c20056;
      8'h74: data = 64'h10d000f00c30057;
      8'h75: data = 64'h10b000d00c40058;
      8'h76: data = 64'h10a000c00c50059;
      8'h77: data = 64'h109000b00c50059;
      8'h78: data = 64'h108000a00c6005a;
      8'h79: data = 64'h106000800c7005b;
      8'h7a: data = 64'h105000700c8005c;
      8'h7b: data = 64'h104000600c8005c;
      8'h7c: data = 64'h103000500c9005d;
      8'h7d: data = 64'h102000400ca005e;
      8'h7e: data = 64'h100000200ca005e;
      8'h7f: data = 64'hff000100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$1
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
      8'h8: data = 64'h100000001;
      8'h9: data = 64'h100000001;
      8'ha: data = 64'h100000001;
      8'hb: data = 64'h100000001;
      8'hc: data = 64'h100000001;
      8'hd: data = 64'h100000001;
      8'he: data = 64'h100000001;
      8'hf: data = 64'h100000001;
      8'h10: data = 64'h100000001;
      8'h11: data = 64'h100000001;
      8'h12: data = 64'h100000001;
      8'h13: data = 64'h100000001;
      8'h14: data = 64'h100000001;
      8'h15: data = 64'h100000001;
      8'h16: data = 64'h100000001;
      8'h17: data = 64'h100000001;
      8'h18: data = 64'h100000001;
      8'h19: data = 64'h100000001;
      8'h1a: data = 64'h100000001;
      8'h1b: data = 64'h100000001;
      8'h1c: data = 64'h100000001;
      8'h1d: data = 64'h100000001;
      8'h1e: data = 64'h100000001;
      8'h1f: data = 64'h100000001;
      8'h20: data = 64'h100000001;
      8'h21: data = 64'h100000001;
      8'h22: data = 64'h100000001;
      8'h23: data = 64'h100000001;
      8'h24: data = 64'h100000001;
      8'h25: data = 64'h100000001;
      8'h26: data = 64'h100000001;
      8'h27: data = 64'h100000001;
      8'h28: data = 64'h100000001;
      8'h29: data = 64'h100000001;
      8'h2a: data = 64'h100000001;
      8'h2b: data = 64'h100000001;
      8'h2c: data = 64'h100000001;
      8'h2d: data = 64'h100000001;
      8'h2e: data = 64'h100000001;
      8'h2f: data = 64'h100000001;
      8'h30: data = 64'h100000001;
      8'h31: data = 64'h100000001;
      8'h32: data = 64'h100000001;
      8'h33: data = 64'h100000001;
      8'h34: data = 64'h100000001;
      8'h35: data = 64'h100000001;
      8'h36: data = 64'h100000001;
      8'h37: data = 64'h100000001;
      8'h38: data = 64'h100000001;
      8'h39: data = 64'h100000001;
      8'h3a: data = 64'h100000001;
      8'h3b: data = 64'h100000001;
      8'h3c: data = 64'h100000001;
      8'h3d: data = 64'h100000001;
      8'h3e: data = 64'h100000001;
      8'h3f: data = 64'h100000001;
      8'h40: data = 64'h100000001;
      8'h41: data = 64'h100000001;
      8'h42: data = 64'h100000001;
      8'h43: data = 64'h100000001;
      8'h44: data = 64'h100000001;
      8'h45: data = 64'h100000001;
      8'h46: data = 64'h100000001;
      8'h47: data = 64'h100000001;
      8'h48: data = 64'h100000001;
      8'h49: data = 64'h100000001;
      8'h4a: data = 64'h100000001;
      8'h4b: data = 64'h100000001;
      8'h4c: data = 64'h100000001;
      8'h4d: data = 64'h100000001;
      8'h4e: data = 64'h100000001;
      8'h4f: data = 64'h100000001;
      8'h50: data = 64'h100000001;
      8'h51: data = 64'h100000001;
      8'h52: data = 64'h100000001;
      8'h53: data = 64'h100000001;
      8'h54: data = 64'h100000001;
      8'h55: data = 64'h100000001;
      8'h56: data = 64'h100000001;
      8'h57: data = 64'h100000001;
      8'h58: data = 64'h100000001;
      8'h59: data = 64'h100000001;
      8'h5a: data = 64'h100000001;
      8'h5b: data = 64'h100000001;
      8'h5c: data = 64'h100000001;
      8'h5d: data = 64'h100000001;
      8'h5e: data = 64'h100000001;
      8'h5f: data = 64'h100000001;
      8'h60: data = 64'h100000001;
      8'h61: data = 64'h100000001;
      8'h62: data = 64'h100000001;
      8'h63: data = 64'h100000001;
      8'h64: data = 64'h100000001;
      8'h65: data = 64'h100000001;
      8'h66: data = 64'h100000001;
      8'h67: data = 64'h100000001;
      8'h68: data = 64'h100000001;
      8'h69: data = 64'h100000001;
      8'h6a: data = 64'h100000001;
      8'h6b: data = 64'h100000001;
      8'h6c: data = 64'h100000001;
      8'h6d: data = 64'h100000001;
      8'h6e: data = 64'h100000001;
      8'h6f: data = 64'h100000001;
      8'h70: data = 64'h100000001;
      8'h71: data = 64'h100000001;
      8'h72: data = 64'h100000001;
      8'h73: data = 64'h100000001;
      8'h74: data = 64'h100000001;
      8'h75: data = 64'h100000001;
      8'h76: data = 64'h100000001;
      8'h77: data = 64'h100000001;
      8'h78: data = 64'h100000001;
      8'h79: data = 64'h100000001;
      8'h7a: data = 64'h100000001;
      8'h7b: data = 64'h100000001;
      8'h7c: data = 64'h100000001;
      8'h7d: data = 64'h100000001;
      8'h7e: data = 64'h100000001;
      8'h7f: data = 64'h100000001;
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
      8'h8: data = 64'h100000001;
      8'h9: data = 64'h100000001;
      8'ha: data = 64'h100000001;
      8'hb: data = 64'h100000001;
      8'hc: data = 64'h100000001;
      8'hd: data = 64'h100000001;
      8'he: data = 64'h100000001;
      8'hf: data = 64'h100000001;
      8'h10: data = 64'h100000001;
      8'h11: data = 64'h100000001;
      8'h12: data = 64'h100000001;
      8'h13: data = 64'h100000001;
      8'h14: data = 64'h100000001;
      8'h15: data = 64'h100000001;
      8'h16: data = 64'h100000001;
      8'h17: data = 64'h100000001;
      8'h18: data = 64'h100000001;
      8'h19: data = 64'h100000001;
      8'h1a: data = 64'h100000001;
      8'h1b: data = 64'h100000001;
      8'h1c: data = 64'h100000001;
      8'h1d: data = 64'h100000001;
      8'h1e: data = 64'h100000001;
      8'h1f: data = 64'h100000001;
      8'h20: data = 64'h100000001;
      8'h21: data = 64'h100000001;
      8'h22: data = 64'h100000001;
      8'h23: data = 64'h100000001;
      8'h24: data = 64'h100000001;
      8'h25: data = 64'h100000001;
      8'h26: data = 64'h100000001;
      8'h27: data = 64'h100000001;
      8'h28: data = 64'h100000001;
      8'h29: data = 64'h100000001;
      8'h2a: data = 64'h100000001;
      8'h2b: data = 64'h100000001;
      8'h2c: data = 64'h100000001;
      8'h2d: data = 64'h100000001;
      8'h2e: data = 64'h100000001;
      8'h2f: data = 64'h100000001;
      8'h30: data = 64'h100000001;
      8'h31: data = 64'h100000001;
      8'h32: data = 64'h100000001;
      8'h33: data = 64'h100000001;
      8'h34: data = 64'h100000001;
      8'h35: data = 64'h100000001;
      8'h36: data = 64'h100000001;
      8'h37: data = 64'h100000001;
      8'h38: data = 64'h100000001;
      8'h39: data = 64'h100000001;
      8'h3a: data = 64'h100000001;
      8'h3b: data = 64'h100000001;
      8'h3c: data = 64'h100000001;
      8'h3d: data = 64'h100000001;
      8'h3e: data = 64'h100000001;
      8'h3f: data = 64'h100000001;
      8'h40: data = 64'h100000001;
      8'h41: data = 64'h100000001;
      8'h42: data = 64'h100000001;
      8'h43: data = 64'h100000001;
      8'h44: data = 64'h100000001;
      8'h45: data = 64'h100000001;
      8'h46: data = 64'h100000001;
      8'h47: data = 64'h100000001;
      8'h48: data = 64'h100000001;
      8'h49: data = 64'h100000001;
      8'h4a: data = 64'h100000001;
      8'h4b: data = 64'h100000001;
      8'h4c: data = 64'h100000001;
      8'h4d: data = 64'h100000001;
      8'h4e: data = 64'h100000001;
      8'h4f: data = 64'h100000001;
      8'h50: data = 64'h100000001;
      8'h51: data = 64'h100000001;
      8'h52: data = 64'h100000001;
      8'h53: data = 64'h100000001;
      8'h54: data = 64'h100000001;
      8'h55: data = 64'h100000001;
      8'h56: data = 64'h100000001;
      8'h57: data = 64'h100000001;
      8'h58: data = 64'h100000001;
      8'h59: data = 64'h100000001;
      8'h5a: data = 64'h100000001;
      8'h5b: data = 64'h100000001;
      8'h5c: data = 64'h100000001;
      8'h5d: data = 64'h100000001;
      8'h5e: data = 64'h100000001;
      8'h5f: data = 64'h100000001;
      8'h60: data = 64'h100000001;
      8'h61: data = 64'h100000001;
      8'h62: data = 64'h100000001;
      8'h63: data = 64'h100000001;
      8'h64: data = 64'h100000001;
      8'h65: data = 64'h100000001;
      8'h66: data = 64'h100000001;
      8'h67: data = 64'h100000001;
      8'h68: data = 64'h100000001;
      8'h69: data = 64'h100000001;
      8'h6a: data = 64'h100000001;
      8'h6b: data = 64'h100000001;
      8'h6c: data = 64'h100000001;
      8'h6d: data = 64'h100000001;
      8'h6e: data = 64'h100000001;
      8'h6f: data = 64'h100000001;
      8'h70: data = 64'h100000001;
      8'h71: data = 64'h100000001;
      8'h72: data = 64'h100000001;
      8'h73: data = 64'h100000001;
      8'h74: data = 64'h100000001;
      8'h75: data = 64'h100000001;
      8'h76: data = 64'h100000001;
      8'h77: data = 64'h100000001;
      8'h78: data = 64'h100000001;
      8'h79: data = 64'h100000001;
      8'h7a: data = 64'h100000001;
      8'h7b: data = 64'h100000001;
      8'h7c: data = 64'h100000001;
      8'h7d: data = 64'h100000001;
      8'h7e: data = 64'h100000001;
      8'h7f: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$1
module top$pipeline$control$late(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h80;
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
    reg [63:0] mem[128:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
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
module top$pipeline$control$templates(ray,scanline,segment,wx$0,wx$1,wy$0,wy$1);
    
    // Module arguments
    input wire  [15:0] ray;
    input wire  [15:0] scanline;
    input wire  [15:0] segment;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    
    // Constant declarations
    localparam  stride = 16'h0;
    
    // Stub signals
    reg  [31:0] wx_rom$0$address;
    wire  [15:0] wx_rom$0$data;
    reg  [31:0] wx_rom$1$address;
    wire  [15:0] wx_rom$1$data;
    reg  [31:0] wy_rom$0$address;
    wire  [15:0] wy_rom$0$data;
    reg  [31:0] wy_rom$1$address;
    wire  [15:0] wy_rom$1$data;
    
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
    top$pipeline$control$templates$wy_rom$0 wy_rom$0(
        .address(wy_rom$0$address),
        .data(wy_rom$0$data)
    );
    top$pipeline$control$templates$wy_rom$1 wy_rom$1(
        .address(wy_rom$1$address),
        .data(wy_rom$1$data)
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
    end
    
endmodule // top$pipeline$control$templates
module top$pipeline$control$templates$wx_rom$0(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h5d;
      'h1: data = 16'ha3;
      'h2: data = 16'h8c;
      'h3: data = 16'hd2;
      'h4: data = 16'h75;
      'h5: data = 16'h5e;
      'h6: data = 16'ha4;
      'h7: data = 16'hea;
      'h8: data = 16'h8d;
      'h9: data = 16'h76;
      'ha: data = 16'hbc;
      'hb: data = 16'h5f;
      'hc: data = 16'ha5;
      'hd: data = 16'h8e;
      'he: data = 16'hd4;
      'hf: data = 16'h77;
      'h10: data = 16'h60;
      'h11: data = 16'ha6;
      'h12: data = 16'hec;
      'h13: data = 16'h8f;
      'h14: data = 16'h78;
      'h15: data = 16'hbe;
      'h16: data = 16'h61;
      'h17: data = 16'ha7;
      'h18: data = 16'h90;
      'h19: data = 16'hd6;
      'h1a: data = 16'h79;
      'h1b: data = 16'h62;
      'h1c: data = 16'ha8;
      'h1d: data = 16'hee;
      'h1e: data = 16'h91;
      'h1f: data = 16'h7a;
      'h20: data = 16'hc0;
      'h21: data = 16'h63;
      'h22: data = 16'ha9;
      'h23: data = 16'h92;
      'h24: data = 16'hd8;
      'h25: data = 16'h7b;
      'h26: data = 16'h64;
      'h27: data = 16'haa;
      'h28: data = 16'hf0;
      'h29: data = 16'h93;
      'h2a: data = 16'h7c;
      'h2b: data = 16'hc2;
      'h2c: data = 16'h65;
      'h2d: data = 16'hab;
      'h2e: data = 16'h94;
      'h2f: data = 16'hda;
      'h30: data = 16'h7d;
      'h31: data = 16'h66;
      'h32: data = 16'hac;
      'h33: data = 16'hf2;
      'h34: data = 16'h95;
      'h35: data = 16'h7e;
      'h36: data = 16'hc4;
      'h37: data = 16'h67;
      'h38: data = 16'had;
      'h39: data = 16'h96;
      'h3a: data = 16'hdc;
      'h3b: data = 16'h7f;
      'h3c: data = 16'h68;
      'h3d: data = 16'hae;
      'h3e: data = 16'hf4;
      'h3f: data = 16'h97;
      'h40: data = 16'h80;
      'h41: data = 16'hc6;
      'h42: data = 16'h69;
      'h43: data = 16'haf;
      'h44: data = 16'h98;
      'h45: data = 16'hde;
      'h46: data = 16'h81;
      'h47: data = 16'h6a;
      'h48: data = 16'hb0;
      'h49: data = 16'hf6;
      'h4a: data = 16'h99;
      'h4b: data = 16'h82;
      'h4c: data = 16'hc8;
      'h4d: data = 16'h6b;
      'h4e: data = 16'hb1;
      'h4f: data = 16'h9a;
      'h50: data = 16'he0;
      'h51: data = 16'h83;
      'h52: data = 16'h6c;
      'h53: data = 16'hb2;
      'h54: data = 16'hf8;
      'h55: data = 16'h9b;
      'h56: data = 16'h84;
      'h57: data = 16'hca;
      'h58: data = 16'h6d;
      'h59: data = 16'hb3;
      'h5a: data = 16'h9c;
      'h5b: data = 16'he2;
      'h5c: data = 16'h85;
      'h5d: data = 16'h6e;
      'h5e: data = 16'hb4;
      'h5f: data = 16'hfa;
      'h60: data = 16'h9d;
      'h61: data = 16'h86;
      'h62: data = 16'hcc;
      'h63: data = 16'h6f;
      'h64: data = 16'hb5;
      'h65: data = 16'h9e;
      'h66: data = 16'he4;
      'h67: data = 16'h87;
      'h68: data = 16'h70;
      'h69: data = 16'hb6;
      'h6a: data = 16'hfc;
      'h6b: data = 16'h9f;
      'h6c: data = 16'h88;
      'h6d: data = 16'hce;
      'h6e: data = 16'h71;
      'h6f: data = 16'hb7;
      'h70: data = 16'ha0;
      'h71: data = 16'he6;
      'h72: data = 16'h89;
      'h73: data = 16'h72;
      'h74: data = 16'hb8;
      'h75: data = 16'hfe;
      'h76: data = 16'ha1;
      'h77: data = 16'h8a;
      'h78: data = 16'hd0;
      'h79: data = 16'h73;
      'h7a: data = 16'hb9;
      'h7b: data = 16'ha2;
      'h7c: data = 16'he8;
      'h7d: data = 16'h8b;
      'h7e: data = 16'h74;
      'h7f: data = 16'hba;
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
        'h0: data = 16'ha3;
      'h1: data = 16'he9;
      'h2: data = 16'h8c;
      'h3: data = 16'h75;
      'h4: data = 16'hbb;
      'h5: data = 16'h5e;
      'h6: data = 16'ha4;
      'h7: data = 16'h8d;
      'h8: data = 16'hd3;
      'h9: data = 16'h76;
      'ha: data = 16'h5f;
      'hb: data = 16'ha5;
      'hc: data = 16'heb;
      'hd: data = 16'h8e;
      'he: data = 16'h77;
      'hf: data = 16'hbd;
      'h10: data = 16'h60;
      'h11: data = 16'ha6;
      'h12: data = 16'h8f;
      'h13: data = 16'hd5;
      'h14: data = 16'h78;
      'h15: data = 16'h61;
      'h16: data = 16'ha7;
      'h17: data = 16'hed;
      'h18: data = 16'h90;
      'h19: data = 16'h79;
      'h1a: data = 16'hbf;
      'h1b: data = 16'h62;
      'h1c: data = 16'ha8;
      'h1d: data = 16'h91;
      'h1e: data = 16'hd7;
      'h1f: data = 16'h7a;
      'h20: data = 16'h63;
      'h21: data = 16'ha9;
      'h22: data = 16'hef;
      'h23: data = 16'h92;
      'h24: data = 16'h7b;
      'h25: data = 16'hc1;
      'h26: data = 16'h64;
      'h27: data = 16'haa;
      'h28: data = 16'h93;
      'h29: data = 16'hd9;
      'h2a: data = 16'h7c;
      'h2b: data = 16'h65;
      'h2c: data = 16'hab;
      'h2d: data = 16'hf1;
      'h2e: data = 16'h94;
      'h2f: data = 16'h7d;
      'h30: data = 16'hc3;
      'h31: data = 16'h66;
      'h32: data = 16'hac;
      'h33: data = 16'h95;
      'h34: data = 16'hdb;
      'h35: data = 16'h7e;
      'h36: data = 16'h67;
      'h37: data = 16'had;
      'h38: data = 16'hf3;
      'h39: data = 16'h96;
      'h3a: data = 16'h7f;
      'h3b: data = 16'hc5;
      'h3c: data = 16'h68;
      'h3d: data = 16'hae;
      'h3e: data = 16'h97;
      'h3f: data = 16'hdd;
      'h40: data = 16'h80;
      'h41: data = 16'h69;
      'h42: data = 16'haf;
      'h43: data = 16'hf5;
      'h44: data = 16'h98;
      'h45: data = 16'h81;
      'h46: data = 16'hc7;
      'h47: data = 16'h6a;
      'h48: data = 16'hb0;
      'h49: data = 16'h99;
      'h4a: data = 16'hdf;
      'h4b: data = 16'h82;
      'h4c: data = 16'h6b;
      'h4d: data = 16'hb1;
      'h4e: data = 16'hf7;
      'h4f: data = 16'h9a;
      'h50: data = 16'h83;
      'h51: data = 16'hc9;
      'h52: data = 16'h6c;
      'h53: data = 16'hb2;
      'h54: data = 16'h9b;
      'h55: data = 16'he1;
      'h56: data = 16'h84;
      'h57: data = 16'h6d;
      'h58: data = 16'hb3;
      'h59: data = 16'hf9;
      'h5a: data = 16'h9c;
      'h5b: data = 16'h85;
      'h5c: data = 16'hcb;
      'h5d: data = 16'h6e;
      'h5e: data = 16'hb4;
      'h5f: data = 16'h9d;
      'h60: data = 16'he3;
      'h61: data = 16'h86;
      'h62: data = 16'h6f;
      'h63: data = 16'hb5;
      'h64: data = 16'hfb;
      'h65: data = 16'h9e;
      'h66: data = 16'h87;
      'h67: data = 16'hcd;
      'h68: data = 16'h70;
      'h69: data = 16'hb6;
      'h6a: data = 16'h9f;
      'h6b: data = 16'he5;
      'h6c: data = 16'h88;
      'h6d: data = 16'h71;
      'h6e: data = 16'hb7;
      'h6f: data = 16'hfd;
      'h70: data = 16'ha0;
      'h71: data = 16'h89;
      'h72: data = 16'hcf;
      'h73: data = 16'h72;
      'h74: data = 16'hb8;
      'h75: data = 16'ha1;
      'h76: data = 16'he7;
      'h77: data = 16'h8a;
      'h78: data = 16'h73;
      'h79: data = 16'hb9;
      'h7a: data = 16'hff;
      'h7b: data = 16'ha2;
      'h7c: data = 16'h8b;
      'h7d: data = 16'hd1;
      'h7e: data = 16'h74;
      'h7f: data = 16'h5d;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wx_rom$1
module top$pipeline$control$templates$wy_rom$0(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h0;
      'h1: data = 16'h3a;
      'h2: data = 16'h17;
      'h3: data = 16'h51;
      'h4: data = 16'h8b;
      'h5: data = 16'h22;
      'h6: data = 16'h5c;
      'h7: data = 16'h39;
      'h8: data = 16'h73;
      'h9: data = 16'ha;
      'ha: data = 16'h44;
      'hb: data = 16'h21;
      'hc: data = 16'h5b;
      'hd: data = 16'h95;
      'he: data = 16'h2c;
      'hf: data = 16'h9;
      'h10: data = 16'h43;
      'h11: data = 16'h7d;
      'h12: data = 16'h14;
      'h13: data = 16'h4e;
      'h14: data = 16'h2b;
      'h15: data = 16'h65;
      'h16: data = 16'h9f;
      'h17: data = 16'h36;
      'h18: data = 16'h13;
      'h19: data = 16'h4d;
      'h1a: data = 16'h87;
      'h1b: data = 16'h1e;
      'h1c: data = 16'h58;
      'h1d: data = 16'h35;
      'h1e: data = 16'h6f;
      'h1f: data = 16'h6;
      'h20: data = 16'h40;
      'h21: data = 16'h1d;
      'h22: data = 16'h57;
      'h23: data = 16'h91;
      'h24: data = 16'h28;
      'h25: data = 16'h62;
      'h26: data = 16'h3f;
      'h27: data = 16'h79;
      'h28: data = 16'h10;
      'h29: data = 16'h4a;
      'h2a: data = 16'h27;
      'h2b: data = 16'h61;
      'h2c: data = 16'h9b;
      'h2d: data = 16'h32;
      'h2e: data = 16'hf;
      'h2f: data = 16'h49;
      'h30: data = 16'h83;
      'h31: data = 16'h1a;
      'h32: data = 16'h54;
      'h33: data = 16'h31;
      'h34: data = 16'h6b;
      'h35: data = 16'h2;
      'h36: data = 16'h3c;
      'h37: data = 16'h19;
      'h38: data = 16'h53;
      'h39: data = 16'h8d;
      'h3a: data = 16'h24;
      'h3b: data = 16'h5e;
      'h3c: data = 16'h3b;
      'h3d: data = 16'h75;
      'h3e: data = 16'hc;
      'h3f: data = 16'h46;
      'h40: data = 16'h23;
      'h41: data = 16'h5d;
      'h42: data = 16'h97;
      'h43: data = 16'h2e;
      'h44: data = 16'hb;
      'h45: data = 16'h45;
      'h46: data = 16'h7f;
      'h47: data = 16'h16;
      'h48: data = 16'h50;
      'h49: data = 16'h2d;
      'h4a: data = 16'h67;
      'h4b: data = 16'ha1;
      'h4c: data = 16'h38;
      'h4d: data = 16'h15;
      'h4e: data = 16'h4f;
      'h4f: data = 16'h89;
      'h50: data = 16'h20;
      'h51: data = 16'h5a;
      'h52: data = 16'h37;
      'h53: data = 16'h71;
      'h54: data = 16'h8;
      'h55: data = 16'h42;
      'h56: data = 16'h1f;
      'h57: data = 16'h59;
      'h58: data = 16'h93;
      'h59: data = 16'h2a;
      'h5a: data = 16'h7;
      'h5b: data = 16'h41;
      'h5c: data = 16'h7b;
      'h5d: data = 16'h12;
      'h5e: data = 16'h4c;
      'h5f: data = 16'h29;
      'h60: data = 16'h63;
      'h61: data = 16'h9d;
      'h62: data = 16'h34;
      'h63: data = 16'h11;
      'h64: data = 16'h4b;
      'h65: data = 16'h85;
      'h66: data = 16'h1c;
      'h67: data = 16'h56;
      'h68: data = 16'h33;
      'h69: data = 16'h6d;
      'h6a: data = 16'h4;
      'h6b: data = 16'h3e;
      'h6c: data = 16'h1b;
      'h6d: data = 16'h55;
      'h6e: data = 16'h8f;
      'h6f: data = 16'h26;
      'h70: data = 16'h60;
      'h71: data = 16'h3d;
      'h72: data = 16'h77;
      'h73: data = 16'he;
      'h74: data = 16'h48;
      'h75: data = 16'h25;
      'h76: data = 16'h5f;
      'h77: data = 16'h99;
      'h78: data = 16'h30;
      'h79: data = 16'hd;
      'h7a: data = 16'h47;
      'h7b: data = 16'h81;
      'h7c: data = 16'h18;
      'h7d: data = 16'h52;
      'h7e: data = 16'h2f;
      'h7f: data = 16'h69;
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
        'h0: data = 16'h40;
      'h1: data = 16'h7a;
      'h2: data = 16'h11;
      'h3: data = 16'h4b;
      'h4: data = 16'h28;
      'h5: data = 16'h62;
      'h6: data = 16'h9c;
      'h7: data = 16'h33;
      'h8: data = 16'h10;
      'h9: data = 16'h4a;
      'ha: data = 16'h84;
      'hb: data = 16'h1b;
      'hc: data = 16'h55;
      'hd: data = 16'h32;
      'he: data = 16'h6c;
      'hf: data = 16'h3;
      'h10: data = 16'h3d;
      'h11: data = 16'h1a;
      'h12: data = 16'h54;
      'h13: data = 16'h8e;
      'h14: data = 16'h25;
      'h15: data = 16'h5f;
      'h16: data = 16'h3c;
      'h17: data = 16'h76;
      'h18: data = 16'hd;
      'h19: data = 16'h47;
      'h1a: data = 16'h24;
      'h1b: data = 16'h5e;
      'h1c: data = 16'h98;
      'h1d: data = 16'h2f;
      'h1e: data = 16'hc;
      'h1f: data = 16'h46;
      'h20: data = 16'h80;
      'h21: data = 16'h17;
      'h22: data = 16'h51;
      'h23: data = 16'h2e;
      'h24: data = 16'h68;
      'h25: data = 16'ha2;
      'h26: data = 16'h39;
      'h27: data = 16'h16;
      'h28: data = 16'h50;
      'h29: data = 16'h8a;
      'h2a: data = 16'h21;
      'h2b: data = 16'h5b;
      'h2c: data = 16'h38;
      'h2d: data = 16'h72;
      'h2e: data = 16'h9;
      'h2f: data = 16'h43;
      'h30: data = 16'h20;
      'h31: data = 16'h5a;
      'h32: data = 16'h94;
      'h33: data = 16'h2b;
      'h34: data = 16'h8;
      'h35: data = 16'h42;
      'h36: data = 16'h7c;
      'h37: data = 16'h13;
      'h38: data = 16'h4d;
      'h39: data = 16'h2a;
      'h3a: data = 16'h64;
      'h3b: data = 16'h9e;
      'h3c: data = 16'h35;
      'h3d: data = 16'h12;
      'h3e: data = 16'h4c;
      'h3f: data = 16'h86;
      'h40: data = 16'h1d;
      'h41: data = 16'h57;
      'h42: data = 16'h34;
      'h43: data = 16'h6e;
      'h44: data = 16'h5;
      'h45: data = 16'h3f;
      'h46: data = 16'h1c;
      'h47: data = 16'h56;
      'h48: data = 16'h90;
      'h49: data = 16'h27;
      'h4a: data = 16'h61;
      'h4b: data = 16'h3e;
      'h4c: data = 16'h78;
      'h4d: data = 16'hf;
      'h4e: data = 16'h49;
      'h4f: data = 16'h26;
      'h50: data = 16'h60;
      'h51: data = 16'h9a;
      'h52: data = 16'h31;
      'h53: data = 16'he;
      'h54: data = 16'h48;
      'h55: data = 16'h82;
      'h56: data = 16'h19;
      'h57: data = 16'h53;
      'h58: data = 16'h30;
      'h59: data = 16'h6a;
      'h5a: data = 16'h1;
      'h5b: data = 16'h3b;
      'h5c: data = 16'h18;
      'h5d: data = 16'h52;
      'h5e: data = 16'h8c;
      'h5f: data = 16'h23;
      'h60: data = 16'h5d;
      'h61: data = 16'h3a;
      'h62: data = 16'h74;
      'h63: data = 16'hb;
      'h64: data = 16'h45;
      'h65: data = 16'h22;
      'h66: data = 16'h5c;
      'h67: data = 16'h96;
      'h68: data = 16'h2d;
      'h69: data = 16'ha;
      'h6a: data = 16'h44;
      'h6b: data = 16'h7e;
      'h6c: data = 16'h15;
      'h6d: data = 16'h4f;
      'h6e: data = 16'h2c;
      'h6f: data = 16'h66;
      'h70: data = 16'ha0;
      'h71: data = 16'h37;
      'h72: data = 16'h14;
      'h73: data = 16'h4e;
      'h74: data = 16'h88;
      'h75: data = 16'h1f;
      'h76: data = 16'h59;
      'h77: data = 16'h36;
      'h78: data = 16'h70;
      'h79: data = 16'h7;
      'h7a: data = 16'h41;
      'h7b: data = 16'h1e;
      'h7c: data = 16'h58;
      'h7d: data = 16'h92;
      'h7e: data = 16'h29;
      'h7f: data = 16'h6;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wy_rom$1
